#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit render [ENV] -o DIR [--samples N] [--lights FILE]: the sphere grid by Monte Carlo with the
// path tracer document's BSDF and by the split sum, with the split sum's error.
void addRenderCommand(CLI::App& app);

// iblkit render-report --out docs/split-sum-error.md: the split sum's error on the report's
// environments, with both reference BSDFs, and the pictures.
void addRenderReportCommand(CLI::App& app);

} // namespace iblkit::cli
