#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit bench [ENV...] --out DIR: run time against error, measured against converged references.
void addBenchCommand(CLI::App& app);

} // namespace iblkit::cli
