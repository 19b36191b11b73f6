#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit compile-all [MANIFEST] -o DIR [--only FORMS]: every shader of hlsl/shaders.json in
// every form, one summary line per shader.
void addCompileAllCommand(CLI::App& app);

} // namespace iblkit::cli
