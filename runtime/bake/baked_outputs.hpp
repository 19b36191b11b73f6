#pragma once

#include "bake_outputs.hpp"
#include "bake_plan.hpp"
#include "bake_progress.hpp"
#include "bake_settings.hpp"
#include "environment_input.hpp"
#include "gpu_steps.hpp"
#include "kernels/built_in_kernels.hpp"
#include "kernels/compiled_kernel_cache.hpp"

#include <future>
#include <optional>
#include <string>

namespace iblkit::cache {
class ContentStore;
}

namespace iblkit::bake {

class BakeSession;

// The device's values of every output a bake writes (before any 16-bit rounding): each from the
// cache where it holds the output's key (bake_cache.hpp), computed on the device otherwise and
// then stored. With every output cached, no device is opened at all. With validation on, the cache
// is neither read nor written.
struct BakedOutputs {
    std::optional<BakedTexture> specular, lut, irradiance; // those the plan needs
    std::optional<BakedTexture> lobeTable;                 // where the plan's specular chain is read through it
    IrradianceSh sh; // of the environment without the lights the recipe took out
    std::vector<shading::EnvironmentLight> lights; // those the recipe took out
    uint32_t lightLevel = 0;                         // the first mip prefiltered without them (shading::lightLevelOf)
    std::string previewPng; // the PNG file's bytes: cached encoded, as encoding is most of a cached bake's time
    float previewExposure = 1;
    std::string device;
    std::vector<std::string> cacheWarnings; // why an output could not be cached
    kernels::CompiledKernelCache::Counts compiledKernels; // the kernels the cache held, and those compiled
    size_t pipelineCacheBytes = 0;                        // the Vulkan pipeline cache data an earlier bake left
    kernels::KernelCompileCounts kernelCompiles;           // taken from the program's built-in kernels, and compiled
    double kernelCompileMilliseconds = 0;                 // on the threads beside the steps
    bool deviceUnconfirmed = false; // every output cached under the remembered device's keys (DeviceSearch::confirmLater)
};

// The device the cache keys name, found on a thread while the input loads (a Vulkan instance
// takes about 0.1 s on lavapipe, a cached bake's largest part); none without a cache. (Opening the
// whole device early for a bake without a cache gained nothing: the load and the kernels' threads
// already keep both cores busy.)
std::shared_future<vulkan::DeviceInfo> findDeviceEarly(const BakeSettings& settings);

// How a bake finds the device its cache keys name: the search findDeviceEarly started, and the
// device the last such bake ran on (remembered_facts.hpp), if any.
struct DeviceSearch {
    std::shared_future<vulkan::DeviceInfo> found;
    std::optional<vulkan::DeviceInfo> remembered;
    // Whether a bake whose outputs were all cached under the remembered device's keys leaves the
    // comparison with the real device to deviceAsRemembered, before its files are committed: the
    // write then overlaps the search.
    bool confirmLater = false;
};

// Decodes `input` (decodeEnvironment) if the cache lacks an output. With a session, the device work
// runs on its device and kernels (bake_session.hpp).
BakedOutputs bakeOutputs(const ResolvedSettings& settings, EnvironmentInput& input, const BakePlan& plan,
                         const std::string& toolVersion, BakeProgress& progress, cache::ContentStore* store,
                         const DeviceSearch& device = {}, BakeSession* session = nullptr);

// Whether the device outputs.deviceUnconfirmed were read for is the one the bake runs on (true
// for outputs that were not left unconfirmed). When it is not, the real device is remembered, the
// remembered one forgotten: the maps must be made again.
bool deviceAsRemembered(const BakedOutputs& outputs, DeviceSearch& search, cache::ContentStore& store,
                        const vulkan::ContextOptions& options);

// The device a bake with `options` runs on.
vulkan::DeviceInfo chosenDevice(const vulkan::ContextOptions& options);

// The environment's mean radiance, in luminance: its maps' (from L00 of their SH projection) and
// its lights', whatever the recipe took out.
double meanLuminance(const IrradianceSh& sh, const std::vector<shading::EnvironmentLight>& lights = {});

// Exposure that maps the environment's mean luminance to 0.4 before the filmic curve, within
// [kMinPreviewExposure, kMaxPreviewExposure].
float previewExposure(const IrradianceSh& sh, const std::vector<shading::EnvironmentLight>& lights = {});

} // namespace iblkit::bake
