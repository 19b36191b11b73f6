#pragma once

#include "bake_directory.hpp"
#include "bake_outputs.hpp"
#include "bake_plan.hpp"
#include "baked_outputs.hpp"
#include "content_store.hpp"
#include "environment_input.hpp"
#include "kernels/built_in_kernels.hpp"
#include "kernels/compiled_kernel_cache.hpp"
#include "bake_progress.hpp"
#include "bake_settings.hpp"
#include "texel_checks.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::bake {

class BakeSession;

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
    std::vector<std::string> sceneNotes;  // what the scene's reader assumed or clamped (BakePlan::notes)
    double kernelCompileMilliseconds = 0; // on the two threads beside the steps (BakeKernels), summed
    kernels::KernelCompileCounts kernelCompiles; // taken from the program's built-in kernels, and compiled from source
};

// Bakes the environment of `settings` into settings.outputDir: specular.ktx2, brdf_lut.ktx2,
// irradiance.ktx2, preview.png and manifest.json (and .dds / exr/ when asked), all or nothing;
// with settings.scene, only what its materials need (bake_plan.hpp); with settings.cache, each
// output the cache holds is taken from it (baked_outputs.hpp). The three steps below, in order.
// Throws BakeError, image_io::ImageError, compiler::CompileError or vulkan::VulkanError.
BakeSummary bakeEnvironment(const BakeSettings& settings, const std::string& toolVersion, BakeProgress& progress);

// The steps of a bake, apart for the library's façade (runtime/api/): it keeps the maps in memory
// without a folder, and tells a refusal of what was asked (prepareBake) from a bake that failed.
enum class BakeDestination { Folder, Memory };

// What a bake asked and read, before any device work.
struct PreparedBake {
    ResolvedSettings settings; // what was asked, resolved once; the face size and chain from the input
    std::chrono::steady_clock::time_point started;
    std::unique_ptr<BakeDirectory> directory; // the output folder claimed; none for a bake kept in memory
    EnvironmentInput input;
    BakePlan plan;
    std::optional<cache::ContentStore> store; // settings.cache's, where the bake uses it (usesCache)
    DeviceSearch device; // findDeviceEarly's, started before the input loads, and the remembered device
    cache::ContentStore::Counts countsBeforeMaps; // the store's, for maps made again (writeBake)
    BakeSession* session = nullptr; // the device and kernels the bake shares with others (bake_session.hpp)
};

// The settings checked, the output folder claimed (for a Folder), the scene and the environment
// read, the plan made, the cache opened: every refusal of what was asked comes from here.
// With a session, nothing here touches it (a batch prepares the next bake on another thread while
// the session's device computes this one); the device work then runs on it.
PreparedBake prepareBake(const BakeSettings& settings, BakeDestination destination, BakeProgress& progress,
                         BakeSession* session = nullptr);

// The maps as the files hold them before their 16-bit rounding and the half-range policy: the
// cubes in the profile's frame, the specular's "iblkit.shading" key set.
struct ComputedMaps {
    BakedOutputs outputs;
    std::string shadingRecord; // shadingJson, compact, as specular.ktx2's "iblkit.shading"
    cache::ContentStore::Counts cache; // zeros without a cache or with validation on
};
ComputedMaps computeMaps(PreparedBake& prepared, const std::string& toolVersion, BakeProgress& progress);

// Writes the maps into the claimed folder, all or nothing.
BakeSummary writeBake(PreparedBake& prepared, ComputedMaps maps, const std::string& toolVersion, BakeProgress& progress);

} // namespace iblkit::bake
