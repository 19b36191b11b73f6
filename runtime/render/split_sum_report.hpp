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
    // The renders' settings: the render's defaults, or smaller for a quick page.
    uint32_t cellSize = kDefaultCellSize;
    uint32_t maxSamples = kDefaultMaxSamples;
    double standardErrorBound = kDefaultStandardErrorBound;
    vulkan::ContextOptions context;
};

// Renders every environment with both reference BSDFs and writes the page: per environment, the
// split sum's error per sphere against each, and the pictures (under split-sum/ beside the page).
// The page, the environment names and the pictures' folder are checked before any render: the
// folder split-sum/ is the report's own, absent, empty or an earlier report's (its manifest.json
// says so), as a bake's folder is. The renders go to a scratch folder; split-sum/ is replaced as a
// whole and the page written at the end, so a failed run leaves an earlier page and its pictures
// as they were. Throws what renderSpheres throws,
// RenderError for an unknown environment and files::FileError for a page that cannot be written.
void writeSplitSumReport(const ReportOptions& options, const std::string& toolVersion, bake::BakeProgress& progress);

} // namespace iblkit::render
