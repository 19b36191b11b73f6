#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit lut-fit [-o FILE]: hlsl/Common/BrdfLutFit.fxh, the polynomial LUT's coefficients fitted
// to the converged LUT.
void addLutFitCommand(CLI::App& app);

} // namespace iblkit::cli
