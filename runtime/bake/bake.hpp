#pragma once

#include "bake_outputs.hpp"
#include "bake_progress.hpp"
#include "bake_settings.hpp"
#include "texel_checks.hpp"

#include <glm/vec3.hpp>

#include <array>

#include <string>
#include <vector>

namespace iblkit::bake {

struct BakeSummary {
    std::filesystem::path outputDir;
    std::string device;
    std::vector<StepTiming> steps;
    double wallMilliseconds;
    std::vector<WrittenFile> files;
    std::array<glm::dvec3, 9> shRadiance; // as in the manifest's irradiance.sh.radiance
    std::vector<HalfRangeClamp> halfRangeClamps; // the textures clamped to the half range, and what it cost
    size_t sanitizedTexels;               // NaN/Inf input texels set to 0 (--sanitize)
    NegativeTexels negativeTexels;        // input texels of negative radiance, clamped to 0
};

// Bakes the environment of `settings` into settings.outputDir: specular.ktx2, brdf_lut.ktx2,
// irradiance.ktx2, preview.png and manifest.json (and .dds / exr/ when asked), all or nothing.
// Throws BakeError, image_io::ImageError, compiler::CompileError or vulkan::VulkanError.
BakeSummary bakeEnvironment(const BakeSettings& settings, const std::string& toolVersion, BakeProgress& progress);

} // namespace iblkit::bake
