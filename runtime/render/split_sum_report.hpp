#pragma once

#include "render/render.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::render {

// The environments docs/split-sum-error.md is measured on: the built-in sky and three of
// blender-data's worlds, one lit by a sun through leaves, one by an open sky between walls, one by
// lamps and windows indoors.
inline const std::vector<std::string> kReportEnvironments = {"sky", "forest", "courtyard", "interior"};

struct ReportOptions {
    std::filesystem::path markdown;             // docs/split-sum-error.md; its pictures go beside it, under split-sum/
    std::filesystem::path cache;                // where blender-data is fetched to (bench_environments.hpp)
    std::vector<std::string> environments = kReportEnvironments;
    std::string command;                        // the command line that wrote it, for the page's header
    vulkan::ContextOptions context;
};

// Renders every environment with both reference BSDFs at the render's defaults and writes the
// page: per environment, the split sum's error per sphere against each, and the pictures.
// Throws what renderSpheres throws, and bench::BenchError for an unknown environment.
void writeSplitSumReport(const ReportOptions& options, const std::string& toolVersion, bake::BakeProgress& progress);

} // namespace iblkit::render
