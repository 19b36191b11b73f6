#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit compile FILE.hlsl -o OUT.spv [forms...] — see docs/compiler.md.
void addCompileCommand(CLI::App& app);

} // namespace iblkit::cli
