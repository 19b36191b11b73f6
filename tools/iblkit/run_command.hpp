#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// Thrown when a run was carried out but an expectation failed: exit code 3.
struct ExpectationsFailed {};

// iblkit run RUN.json [--device D] [--validate]: see docs/run-files.md.
void addRunCommand(CLI::App& app);

} // namespace iblkit::cli
