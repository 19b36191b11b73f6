#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit compile FILE.hlsl -o OUT.spv [forms...] — see docs/compiler.md.
void addCompileCommand(CLI::App& app);

// Thrown after the written outputs are committed when a requested form could not express the
// shader (each reason already printed): the program exits with 4.
struct FormsRefused {};

} // namespace iblkit::cli
