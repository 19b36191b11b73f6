#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit bake [ENV] -o DIR ...: the IBL assets of an environment; see docs/bake.md.
void addBakeCommand(CLI::App& app);

} // namespace iblkit::cli
