#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit shading --out docs/shading.md: every shading recipe against the Monte Carlo reference of
// the split sum's own BSDF, on the shading bench's environments, with the tables and plots.
void addShadingCommand(CLI::App& app);

} // namespace iblkit::cli
