#pragma once

#include "render/render_settings.hpp"
#include "render/sphere_errors.hpp"

#include "bake_outputs.hpp"
#include "bake_progress.hpp"

#include <string>
#include <vector>

namespace iblkit::render {

struct RenderSummary {
    std::filesystem::path outputDir;
    std::string device;
    double meanSamples = 0;               // paths per pixel the reference took, on average
    uint32_t maxSamples = 0;              // and at the most
    double maxRelativeStandardError = 0;  // the reference's, over every sphere pixel
    std::vector<SphereError> spheres;
    std::vector<bake::WrittenFile> files;
    double wallMilliseconds = 0;
};

// Renders the sphere grid twice, by Monte Carlo with the path tracer document's BSDF and lights
// (the reference) and by the split sum from the environment's default bake, and writes both with
// their errors into settings.outputDir, all or nothing (as a bake's folder: bake_directory.hpp).
// A reference that is not within kStandardErrorBound after settings.maxSamples is refused, and
// nothing is written. With settings.splitSumOnly, the split sum alone: its images and the grid. Throws RenderError, bake::BakeError, image_io::ImageError,
// compiler::CompileError or vulkan::VulkanError.
RenderSummary renderSpheres(const RenderSettings& settings, const std::string& toolVersion, bake::BakeProgress& progress);

} // namespace iblkit::render
