#pragma once

#include "bake_outputs.hpp"
#include "content_store.hpp"
#include "kernels/compiled_kernel_cache.hpp"
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
    cache::ContentStore::Counts cache;    // the cache's hits, misses and damaged entries (zeros without a cache)
    std::vector<std::string> cacheWarnings; // why an output could not be cached (the bake went on)
    kernels::CompiledKernelCache::Counts compiledKernels; // kernels taken from the cache and compiled (zeros without a device)
    size_t pipelineCacheBytes = 0;        // Vulkan pipeline cache data an earlier bake on this device left
};

// Bakes the environment of `settings` into settings.outputDir: specular.ktx2, brdf_lut.ktx2,
// irradiance.ktx2, preview.png and manifest.json (and .dds / exr/ when asked), all or nothing;
// with settings.scene, only what its materials need (bake_plan.hpp); with settings.cache, each
// output the cache holds is taken from it (baked_outputs.hpp).
// Throws BakeError, image_io::ImageError, compiler::CompileError or vulkan::VulkanError.
BakeSummary bakeEnvironment(const BakeSettings& settings, const std::string& toolVersion, BakeProgress& progress);

} // namespace iblkit::bake
