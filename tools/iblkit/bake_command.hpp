#pragma once

#include <iblkit/bake.hpp>

#include <CLI/CLI.hpp>

#include <string>

namespace iblkit::cli {

// iblkit bake [ENV] -o DIR ...: the IBL assets of an environment; see docs/bake.md.
void addBakeCommand(CLI::App& app);

// What the input policies changed, on stderr: printed even with --quiet, which silences only progress.
void printPolicyReports(const BakeSummary& summary, const std::string& prefix = {});

} // namespace iblkit::cli
