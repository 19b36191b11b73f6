#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit stress [--out docs/stability.md]: every kernel at its numerical extremes, on every path.
void addStressCommand(CLI::App& app);

} // namespace iblkit::cli
