#include "baked_outputs.hpp"

#include "bake_cache.hpp"
#include "bake_error.hpp"
#include "bake_kernels.hpp"
#include "bake_manifest.hpp"
#include "cache_error.hpp"
#include "content_store.hpp"
#include "bake_device.hpp"
#include "bake_session.hpp"
#include "device_caches.hpp"
#include "remembered_facts.hpp"
#include "float_image.hpp"
#include "kernels/specular_method.hpp"
#include "shading_maps.hpp"
#include "shading/built_lobe_tables.hpp"
#include "vulkan_context.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <unistd.h>

namespace iblkit::bake {
namespace {

double cubeChainBytes(uint32_t size) { return 6.0 * size * size * 16 * 4 / 3; }

std::string gigabytes(double bytes) { return fmt::format("{:.1f} GB", bytes / 1e9); }

// Refuses sizes whose images would not fit, before any of them is made.
void checkMemory(const vulkan::VulkanContext& context, const ResolvedSettings& settings, const EnvironmentInput& input,
                 uint32_t size) {
    const double panorama = double(input.panorama.width) * input.panorama.height * 16;
    // The convolution's energy, centroid and geometry pyramids are each a full RGBA32F chain, as wide as
    // the source up to 512², half as wide above.
    const double pyramids =
        kernels::isConvolutionMethod(settings.specularMethod) ? 3 * cubeChainBytes(kernels::convolutionPyramidSize(size)) : 0;
    const double device = 2 * cubeChainBytes(size) + pyramids + panorama + double(settings.lutSize) * settings.lutSize * 8 +
                          6.0 * settings.irradianceSize * settings.irradianceSize * 16;
    // The host holds each image as floats while it downloads and encodes it.
    const double host = device + 2 * cubeChainBytes(size);
    const double heap = double(context.largestHeapSize());
    const double ram = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
    if (device > heap)
        throw BakeError(fmt::format("this bake needs about {} of device memory; the device's largest heap is {} "
                                    "(lower --size or --lut-size)", gigabytes(device), gigabytes(heap)));
    if (host > ram)
        throw BakeError(fmt::format("this bake needs about {} of memory; the machine has {} (lower --size or --lut-size)",
                                    gigabytes(host), gigabytes(ram)));
}

void checkFiniteOutput(const std::string& name, const std::vector<float>& values) {
    const auto bad = std::count_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); });
    if (bad > 0) throw BakeError(fmt::format("internal error: {} has {} NaN/Inf values", name, bad));
}

BakedTexture download(const vulkan::VulkanContext& context, const vulkan::Image& image, const std::string& name,
                      image_io::PixelFormat format) {
    auto values = image.download(context);
    checkFiniteOutput(name, values);
    if (image.desc().format->channels != image_io::channelCount(format))
        throw BakeError("internal error: " + name + " has the wrong channel count");
    return {name, format, image.desc().width, image.desc().layers, image.desc().mips, std::move(values)};
}

// A cached output back on the device, for the preview to read.
vulkan::Image uploaded(const vulkan::VulkanContext& context, const BakedTexture& texture, const char* format) {
    vulkan::Image image(context, {texture.name, &vulkan::texelFormatNamed(format), texture.size, texture.size, texture.faces,
                                  texture.mips, texture.faces == 6, true});
    image.upload(context, texture.values);
    return image;
}

image_io::PixelFormat lutFormatOf(const ResolvedSettings& settings) {
    return settings.lutFormat == LutFormat::Rg16Float ? image_io::PixelFormat::Rg16Float : image_io::PixelFormat::Rg32Float;
}

std::vector<uint8_t> toRgba8(const std::vector<float>& rgba) {
    std::vector<uint8_t> bytes(rgba.size());
    std::transform(rgba.begin(), rgba.end(), bytes.begin(),
                   [](float v) { return uint8_t(std::lround(std::clamp(v, 0.f, 1.f) * 255.f)); });
    return bytes;
}

// Whether the bake writes the recipe's lobe table: where it writes a specular chain read through it.
bool writesLobeTable(const BakePlan& plan) { return plan.specular && readsLobeTable(*plan.recipe); }

struct Cached {
    std::optional<BakedTexture> specular, lut, irradiance, lobeTable;
    std::optional<IrradianceSh> sh;
    std::optional<std::vector<shading::EnvironmentLight>> lights;
    std::optional<std::string> previewPng;

    bool complete(const BakePlan& plan) const {
        return (!plan.specular || specular) && (!plan.lut || lut) && irradiance && (!plan.recipe->lights || lights) &&
               (!writesLobeTable(plan) || lobeTable) && previewPng;
    }
};

Cached lookUp(cache::ContentStore* store, const BakeKeys& keys, const BakePlan& plan, const ResolvedSettings& settings) {
    Cached cached;
    if (!store) return cached;
    const auto texture = [&](const std::string& key) {
        const auto entry = store->getInPlace(key);
        return entry ? textureFromPayload(entry->payload()) : std::nullopt;
    };
    if (plan.specular) cached.specular = texture(keys.specular);
    if (writesLobeTable(plan)) cached.lobeTable = texture(keys.lobeTable);
    if (plan.lut && (cached.lut = texture(keys.lut))) cached.lut->format = lutFormatOf(settings); // the values are the device's
    if (const auto payload = store->getInPlace(keys.irradiance))
        if (auto entry = irradianceFromPayload(payload->payload())) {
            cached.sh = entry->first;
            cached.irradiance = std::move(entry->second);
        }
    if (plan.recipe->lights)
        if (const auto payload = store->get(keys.lights)) cached.lights = lightsFromPayload(*payload);
    cached.previewPng = store->get(keys.preview);
    return cached;
}

// A cache that cannot be written (a full disk, a read-only folder) costs the next bake its time,
// not this bake its files: the reason goes to the summary as a warning.
void store(cache::ContentStore* store, const std::string& key, std::span<const std::string_view> payload,
           std::vector<std::string>& warnings) {
    if (!store) return;
    try {
        store->put(key, payload);
    } catch (const cache::CacheError& error) {
        if (warnings.empty()) warnings.push_back(std::string(error.what()) + " (the bake goes on without caching it)");
    }
}

void store(cache::ContentStore* cache, const std::string& key, std::string_view payload, std::vector<std::string>& warnings) {
    store(cache, key, std::span(&payload, 1), warnings);
}

// The device the search found, or, where none was started, the one `options` chooses.
vulkan::DeviceInfo foundDevice(const DeviceSearch& search, const vulkan::ContextOptions& options) {
    return search.found.valid() ? search.found.get() : chosenDevice(options);
}

// The device's work, each output taken from the cache where it holds it.
struct DeviceResults {
    vulkan::Image specular, lut;
    Irradiance irradiance;
    std::vector<shading::EnvironmentLight> lights;
    uint32_t lightLevel = 0;
};

// The recipe's lights, taken out of the source wherever a map is made from the rest or the cache
// lacks them (the extraction is deterministic: a cached list is the same list).
TakenOutLights lightsOf(const vulkan::VulkanContext& context, BakeKernels& kernels, const BakePlan& plan, const Cached& cached,
                        const std::function<vulkan::Image&()>& sourceCube, BakeProgress& progress) {
    const auto& recipe = *plan.recipe;
    if (!recipe.lights) return {};
    const bool mapsToMake = (plan.specular && !cached.specular) || !cached.irradiance;
    if (mapsToMake || !cached.lights)
        return takeOutLights(context, sourceCube(), *recipe.lights, kernels.downsample(), progress);
    return {*cached.lights, std::nullopt, {}, {}};
}

vulkan::Image prefilteredSpecular(const vulkan::VulkanContext& context, BakeKernels& kernels, const BakePlan& plan,
                                  vulkan::Image& source, TakenOutLights& taken, uint32_t lightLevel, BakeProgress& progress) {
    SpecularLevels levels{{}, plan.prefilteredMips(), taken.residual ? &*taken.residual : nullptr, lightLevel};
    for (const auto& mip : plan.mips) levels.roughness.push_back(mip.roughness);
    auto* prefilter = kernels.specular();
    if (prefilter) prefilter->setWeighting(plan.recipe->weighting);
    return prefilterLevels(context, source, levels, prefilter, progress);
}

Irradiance irradianceWithLights(const vulkan::VulkanContext& context, BakeKernels& kernels, vulkan::Image& residual,
                                const ResolvedSettings& settings, const BakePlan& plan, const TakenOutLights& taken,
                                BakeProgress& progress) {
    auto irradiance = computeIrradiance(context, kernels.irradiance(), {residual, taken.restMipZero}, settings.irradianceSize, progress,
                                        plan.irradiance, plan.recipe->irradianceSource);
    if (plan.irradiance) addLightTexelsIrradiance(context, irradiance.cube, taken);
    return irradiance;
}

DeviceResults runSteps(const vulkan::VulkanContext& context, BakeKernels& kernels, const ResolvedSettings& settings,
                       const EnvironmentInput& input, uint32_t size, const BakePlan& plan, const Cached& cached,
                       BakeProgress& progress) {
    std::optional<vulkan::Image> source;
    const std::function<vulkan::Image&()> sourceCube = [&]() -> vulkan::Image& {
        if (!source) source.emplace(buildSourceCube(context, input, size, progress));
        return *source;
    };
    const auto& recipe = *plan.recipe;
    auto taken = lightsOf(context, kernels, plan, cached, sourceCube, progress);
    const uint32_t lightLevel = shading::lightLevelOf(recipe, plan.schedule, taken.lights);
    const auto residualCube = [&]() -> vulkan::Image& { return taken.residual ? *taken.residual : sourceCube(); };
    // With the lights taken out of every mip, nothing reads the source cube after the lights step:
    // it goes (at 1024², 128 MiB of the bake's peak).
    const bool residualOnly = taken.residual && lightLevel == 0;
    if (residualOnly) source.reset();
    // The irradiance first: it alone reads the host copy of mip 0, which is gone before the
    // prefilter's pyramids are made (at 1024², 96 MiB of the bake's peak).
    auto irradiance = cached.irradiance ? Irradiance{uploaded(context, *cached.irradiance, "R32G32B32A32_SFLOAT"), *cached.sh}
                                        : irradianceWithLights(context, kernels, residualCube(), settings, plan, taken, progress);
    std::vector<float>().swap(taken.restMipZero);
    auto specular = cached.specular ? uploaded(context, *cached.specular, "R32G32B32A32_SFLOAT")
                                    : prefilteredSpecular(context, kernels, plan, residualOnly ? *taken.residual : sourceCube(), taken,
                                                          lightLevel, progress);
    auto lut = !plan.lut      ? blankBrdfLut(context)
               : cached.lut ? uploaded(context, *cached.lut, "R32G32_SFLOAT")
                            : integrateBrdfLut(context, settings.lutSize, *kernels.lut(), progress);
    return {std::move(specular), std::move(lut), std::move(irradiance), std::move(taken.lights), lightLevel};
}

// Every output's values on the host, from the cache or the device.
BakedOutputs downloaded(const vulkan::VulkanContext& context, BakeKernels& kernels, const ResolvedSettings& settings,
                        const BakePlan& plan, const Cached& cached, DeviceResults& results, BakeProgress& progress) {
    BakedOutputs outputs;
    outputs.device = context.deviceInfo().name;
    outputs.sh = results.irradiance.sh;
    outputs.lights = results.lights;
    outputs.lightLevel = results.lightLevel;
    outputs.previewExposure = previewExposure(results.irradiance.sh, results.lights);
    if (!cached.previewPng) {
        const auto& recipe = *plan.recipe;
        auto lobeTable = lobeTableImage(context, recipe.weighting);
        const auto lights = environmentLightBuffer(context, results.lights);
        const auto preview = renderPreview(context, kernels.preview(),
                                           {results.specular, results.irradiance.cube, results.lut, lobeTable, lights,
                                            recipeParameters(recipe, plan.schedule, results.lights.size(), results.lightLevel)},
                                           outputs.previewExposure, progress);
        progress.begin("outputs");
        progress.part("preview png");
        outputs.previewPng = image_io::encodePng(preview.width, preview.height, toRgba8(preview.rgba));
    } else {
        progress.begin("outputs");
        outputs.previewPng = *cached.previewPng;
    }
    progress.part("download");
    const auto rgba16 = image_io::PixelFormat::Rgba16Float;
    if (plan.specular) outputs.specular = cached.specular ? *cached.specular : download(context, results.specular, "specular", rgba16);
    if (writesLobeTable(plan)) {
        const auto table = shading::builtLobeTable(plan.recipe->weighting);
        outputs.lobeTable = cached.lobeTable ? *cached.lobeTable
                                             : BakedTexture{"lobe_table", image_io::PixelFormat::Rgba32Float, shading::kLobeTableSize,
                                                            1, 1, std::vector<float>(table.begin(), table.end())};
    }
    if (plan.lut) outputs.lut = cached.lut ? *cached.lut : download(context, results.lut, "brdf_lut", lutFormatOf(settings));
    outputs.irradiance = cached.irradiance ? *cached.irradiance : download(context, results.irradiance.cube, "irradiance", rgba16);
    return outputs;
}

// What the cache did not hold, stored; the irradiance cube goes with its SH even where the plan skips it.
void storeComputed(cache::ContentStore* cache, const BakeKeys& keys, const BakePlan& plan, const Cached& cached,
                   BakedOutputs& outputs) {
    if (!cache) return; // the payloads are tens of megabytes at large sizes: none is made for nothing
    auto& warnings = outputs.cacheWarnings;
    if (!cached.specular && outputs.specular) store(cache, keys.specular, texturePayload(*outputs.specular).parts(), warnings);
    if (!cached.lut && outputs.lut) store(cache, keys.lut, texturePayload(*outputs.lut).parts(), warnings);
    if (!cached.irradiance) store(cache, keys.irradiance, irradiancePayload(outputs.sh, *outputs.irradiance).parts(), warnings);
    if (!cached.lights && plan.recipe->lights) store(cache, keys.lights, lightsPayload(outputs.lights), warnings);
    if (!cached.lobeTable && outputs.lobeTable) store(cache, keys.lobeTable, texturePayload(*outputs.lobeTable).parts(), warnings);
    if (!cached.previewPng) store(cache, keys.preview, outputs.previewPng, warnings);
}

// What the cache does not hold, computed on the device, and stored.
BakedOutputs computeOnDevice(const ResolvedSettings& settings, const EnvironmentInput& input, uint32_t size, const BakePlan& plan,
                             const BakeKeys& keys, Cached cached, BakeProgress& progress, cache::ContentStore* cache,
                             BakeSession* session) {
    kernels::KernelCompileCounter compiles;
    const kernels::CountKernelCompiles counting(&compiles);
    // A LUT an earlier bake of the session made is this one's: it depends on the LUT's settings alone.
    const bool lutFromSession = plan.lut && !cached.lut && session && session->lut(settings);
    if (lutFromSession) {
        cached.lut = *session->lut(settings);
        cached.lut->format = lutFormatOf(settings); // the values are the device's, whatever the file's format
    }
    progress.begin("device");
    BakeDevice device(session, settings, cache,
                      NeededOutputs{plan.specular && !cached.specular, plan.irradiance, plan.lut && !cached.lut}, size, progress);
    const auto& context = device.context();
    auto& kernels = device.kernels();
    progress.part("memory check");
    checkMemory(context, settings, input, size);
    progress.end();
    std::optional<DeviceResults> results(runSteps(context, kernels, settings, input, size, plan, cached, progress));
    auto outputs = downloaded(context, kernels, settings, plan, cached, *results, progress);
    if (session && outputs.lut && !cached.lut) session->keepLut(settings, *outputs.lut);
    progress.part("cache entries");
    storeComputed(cache, keys, plan, cached, outputs);
    if (!plan.irradiance) outputs.irradiance.reset();
    progress.part("pipeline cache");
    device.caches().keepPipelineCache(outputs.cacheWarnings);
    outputs.compiledKernels = device.caches().compiledKernels();
    outputs.pipelineCacheBytes = device.caches().pipelineCacheBytesLoaded();
    outputs.kernelCompileMilliseconds = kernels.compileMilliseconds();
    outputs.kernelCompiles = compiles.counts(); // both threads' kernels are made by now
    progress.end();
    progress.begin("tear-down");
    results.reset();
    device.tearDown();
    progress.end();
    return outputs;
}

} // namespace

bool deviceAsRemembered(const BakedOutputs& outputs, DeviceSearch& search, cache::ContentStore& store,
                        const vulkan::ContextOptions& options) {
    if (!outputs.deviceUnconfirmed) return true;
    const auto device = foundDevice(search, options);
    if (sameIdentity(device, *search.remembered)) return true;
    rememberDevice(store, options, device);
    search.remembered.reset();
    return false;
}

std::shared_future<vulkan::DeviceInfo> findDeviceEarly(const BakeSettings& settings) {
    if (!usesCache(settings)) return {};
    return std::async(std::launch::async, [options = settings.context] { return chosenDevice(options); }).share();
}

vulkan::DeviceInfo chosenDevice(const vulkan::ContextOptions& options) {
    const auto devices = vulkan::listDevices();
    return devices[vulkan::chooseDevice(devices, options.device)];
}

double meanLuminance(const IrradianceSh& sh, const std::vector<shading::EnvironmentLight>& lights) {
    const auto luminance = [](const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
    double mean = luminance(sh.shRadiance[0] * 0.282094791773878);
    for (const auto& light : lights) mean += luminance(light.radiance) * light.solidAngle / (4 * std::numbers::pi);
    return mean;
}

float previewExposure(const IrradianceSh& sh, const std::vector<shading::EnvironmentLight>& lights) {
    const double luminance = meanLuminance(sh, lights);
    if (!(luminance > 0) || !std::isfinite(luminance)) return 1.f;
    return float(std::clamp(0.4 / luminance, kMinPreviewExposure, kMaxPreviewExposure));
}

namespace {

// The cache's entries under the keys of the device the bake runs on. With a remembered device
// they are read while the real one is found, and read again only if it is another.
struct CacheLookUp {
    BakeKeys keys;
    Cached cached;
    vulkan::DeviceInfo device;
};

CacheLookUp lookUpEntries(const ResolvedSettings& settings, const EnvironmentInput& input, const BakePlan& plan,
                          const std::string& toolVersion, BakeProgress& progress, cache::ContentStore& store,
                          const DeviceSearch& search) {
    const auto found = [&] { return foundDevice(search, settings.context); };
    const auto entries = [&](const vulkan::DeviceInfo& device) {
        progress.part("keys");
        auto keys = bakeKeys(settings, input, plan, device, toolVersion);
        progress.part("entries");
        auto cached = lookUp(&store, keys, plan, settings);
        return CacheLookUp{std::move(keys), std::move(cached), device};
    };
    if (!search.remembered) {
        progress.part("device identity");
        auto result = entries(found());
        rememberDevice(store, settings.context, result.device);
        return result;
    }
    const auto countsBefore = store.counts();
    auto result = entries(*search.remembered);
    if (search.confirmLater && result.cached.complete(plan)) return result;
    progress.part("device identity");
    const auto device = found();
    if (sameIdentity(device, result.device)) return result;
    store.restoreCounts(countsBefore);
    rememberDevice(store, settings.context, device);
    return entries(device);
}

} // namespace

BakedOutputs bakeOutputs(const ResolvedSettings& settings, EnvironmentInput& input, const BakePlan& plan,
                         const std::string& toolVersion, BakeProgress& progress, cache::ContentStore* store,
                         const DeviceSearch& device, BakeSession* session) {
    const uint32_t size = settings.faceSize;
    if (!usesCache(settings)) store = nullptr;
    if (!store) return computeOnDevice(settings, input, size, plan, {}, {}, progress, nullptr, session);
    progress.begin("cache");
    auto [keys, cached, found] = lookUpEntries(settings, input, plan, toolVersion, progress, *store, device);
    progress.end();
    const bool unconfirmed = device.remembered && device.confirmLater && cached.complete(plan);
    if (!cached.complete(plan)) {
        if (!input.decoded) {
            progress.begin("decode");
            decodeEnvironment(input);
            progress.end();
        }
        return computeOnDevice(settings, input, size, plan, keys, std::move(cached), progress, store, session);
    }
    auto lights = cached.lights.value_or(std::vector<shading::EnvironmentLight>{});
    const uint32_t lightLevel = shading::lightLevelOf(*plan.recipe, plan.schedule, lights);
    const float exposure = previewExposure(*cached.sh, lights);
    BakedOutputs outputs;
    outputs.specular = std::move(cached.specular);
    outputs.lut = std::move(cached.lut);
    if (plan.irradiance) outputs.irradiance = std::move(cached.irradiance);
    outputs.lobeTable = std::move(cached.lobeTable);
    outputs.sh = *cached.sh;
    outputs.lights = std::move(lights);
    outputs.lightLevel = lightLevel;
    outputs.previewPng = std::move(*cached.previewPng);
    outputs.previewExposure = exposure;
    outputs.device = found.name;
    outputs.deviceUnconfirmed = unconfirmed;
    return outputs;
}

} // namespace iblkit::bake
