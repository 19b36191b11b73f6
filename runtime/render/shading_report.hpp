#pragma once

#include "render/shading_bench.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::render {

// The targets docs/shading.md holds each opaque sphere to: the mean of |per-pixel error| no more
// than kMeanTarget above the reference's own noise (0.8 of the mean relative standard error, the
// mean of a normal's magnitude), and the summed error within ±kTotalTarget; glass within
// kGlassTarget.
inline constexpr double kMeanTarget = 0.03, kTotalTarget = 0.02, kGlassTarget = 0.2;
// The diffuse's source (irradiance map and lights) within this of the exact sum at every texel.
inline constexpr double kIrradianceTarget = 0.01;

// A sphere's mean error less the share its reference's noise explains.
double excessError(const SphereError& sphere);
bool meetsTarget(const SphereError& sphere);

struct ShadingReportOptions {
    std::filesystem::path markdown; // docs/shading.md; results.json and the plots go beside it, under shading/
    std::string command;            // the command line that wrote it
};

// results.json, the plots (tools/shading_plot.py) and the page.
void writeShadingReport(const ShadingReportOptions& options, const ShadingBenchOptions& bench,
                        const std::vector<EnvironmentResult>& results);

} // namespace iblkit::render
