#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit consistency [--out docs/consistency.md]: every path against the C++ reference.
void addConsistencyCommand(CLI::App& app);

} // namespace iblkit::cli
