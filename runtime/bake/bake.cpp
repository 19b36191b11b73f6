#include "bake.hpp"

#include "bake_error.hpp"
#include "bake_manifest.hpp"
#include "bake_session.hpp"
#include "lights_gltf.hpp"
#include "remembered_facts.hpp"
#include "shading_maps.hpp"
#include "profiles/cube_frame.hpp"

#include <fmt/core.h>

#include <bit>

namespace iblkit::bake {
namespace {

using Clock = std::chrono::steady_clock;

ManifestFacts factsOf(const PreparedBake& prepared, const BakedOutputs& outputs, const std::string& toolVersion,
                      bool lobeTableFile) {
    const auto& settings = prepared.settings;
    return {toolVersion,           outputs.device,  &prepared.input, &settings,        settings.faceSize, settings.mipCount,
            &outputs.sh,           nullptr,         outputs.previewExposure, &prepared.plan, &outputs.lights,
            outputs.lightLevel,    lobeTableFile};
}

// The cubes from the kit's frame into the profile's, as its files hold them.
void arrangeCubes(const ResolvedSettings& settings, BakedOutputs& outputs) {
    const auto& profile = *settings.engineProfile;
    for (auto* texture : {&outputs.specular, &outputs.lut, &outputs.irradiance, &outputs.lobeTable})
        if (*texture && (*texture)->faces == 6)
            profiles::arrangeCube(profile.frame, (*texture)->values, (*texture)->size, (*texture)->mips,
                                  image_io::channelCount((*texture)->format));
}

} // namespace

PreparedBake prepareBake(const BakeSettings& asked, BakeDestination destination, BakeProgress& progress,
                         BakeSession* session) {
    PreparedBake prepared;
    prepared.started = Clock::now();
    prepared.session = session;
    prepared.settings = resolveSettings(asked);
    auto& settings = prepared.settings;
    if (destination == BakeDestination::Folder && settings.outputDir.empty()) throw BakeError("no output folder (-o DIR)");
    // A scene that cannot be read fails before any device work.
    const auto scene = settings.scene ? std::optional(scene::readSceneMaterials(*settings.scene, settings.strict)) : std::nullopt;
    if (destination == BakeDestination::Folder) {
        if (settings.cache) requireCacheOutsideTarget(*settings.cache, settings.outputDir);
        prepared.directory = std::make_unique<BakeDirectory>(settings.outputDir, settings.environment);
    }

    // A session's device is found once, for all its bakes (computeMaps).
    if (!session) prepared.device.found = findDeviceEarly(settings);
    prepared.device.confirmLater = !session && destination == BakeDestination::Folder;
    progress.begin("load");
    if (usesCache(settings)) prepared.store.emplace(*settings.cache);
    auto* store = prepared.store ? &*prepared.store : nullptr;
    prepared.input = readEnvironment(settings.environment, {settings.sanitize, settings.strict});
    if (store && !session) prepared.device.remembered = rememberedDevice(*store, settings.context);
    if (const auto facts = store ? rememberedFacts(*store, prepared.input) : std::nullopt) {
        takeFacts(prepared.input, *facts); // decoded only if the cache lacks an output
    } else {
        decodeEnvironment(prepared.input);
        if (store) rememberFacts(*store, prepared.input);
    }
    resolveFaceSize(settings, prepared.input.cubeSize);
    prepared.plan = planBake(settings, scene);
    progress.end();
    return prepared;
}

ComputedMaps computeMaps(PreparedBake& prepared, const std::string& toolVersion, BakeProgress& progress) {
    const auto& settings = prepared.settings;
    auto* store = prepared.store ? &*prepared.store : nullptr;
    if (store) prepared.countsBeforeMaps = store->counts();
    if (prepared.session && store && !prepared.device.found.valid()) {
        std::promise<vulkan::DeviceInfo> device;
        device.set_value(prepared.session->device());
        prepared.device.found = device.get_future().share();
    }
    ComputedMaps maps{bakeOutputs(settings, prepared.input, prepared.plan, toolVersion, progress, store, prepared.device,
                                  prepared.session), {}, {}};
    auto& outputs = maps.outputs;
    const auto facts = factsOf(prepared, outputs, toolVersion, outputs.lobeTable.has_value());
    maps.shadingRecord = shadingJson(facts).dump();
    if (outputs.specular) outputs.specular->keyValues["iblkit.shading"] = maps.shadingRecord;
    arrangeCubes(settings, outputs);
    if (store) maps.cache = store->counts();
    return maps;
}

BakeSummary writeBake(PreparedBake& prepared, ComputedMaps maps, const std::string& toolVersion, BakeProgress& progress) {
    const auto& settings = prepared.settings;
    auto& outputs = maps.outputs;
    progress.begin("write");
    const auto facts = factsOf(prepared, outputs, toolVersion, outputs.lobeTable.has_value());
    std::vector<BakedTexture> textures; // what the plan needs: a skipped output is no file
    for (auto* texture : {&outputs.specular, &outputs.lut, &outputs.irradiance, &outputs.lobeTable})
        if (*texture) textures.push_back(std::move(**texture));
    progress.part("half range");
    std::vector<HalfRangeClamp> clamps;
    for (auto& texture : textures)
        if (auto clamp = applyHalfRangePolicy(texture, settings.strict)) clamps.push_back(std::move(*clamp));
    const std::string writer = "iblkit " + toolVersion;
    const auto& folder = prepared.directory->staging();
    std::vector<WrittenFile> files;
    for (const auto& texture : textures) {
        progress.part(texture.name);
        for (auto& file : writeTexture(folder, texture, settings, writer)) files.push_back(std::move(file));
    }
    progress.part("preview, lights, manifest");
    files.push_back(writeBytes(folder, "preview.png", std::as_bytes(std::span(outputs.previewPng))));
    if (!outputs.lights.empty()) {
        const auto gltf = lightsGltf(outputs.lights, writer);
        files.push_back(writeBytes(folder, "lights.gltf", std::as_bytes(std::span(gltf))));
    }

    auto manifestFacts = facts;
    manifestFacts.halfRangeClamps = &clamps;
    auto manifest = bakeManifest(manifestFacts);
    manifest["files"] = filesJson(files);
    const std::string manifestText = manifest.dump(2) + "\n";
    files.push_back(writeBytes(folder, "manifest.json", std::as_bytes(std::span(manifestText))));
    progress.part("commit");
    if (prepared.store && !deviceAsRemembered(outputs, prepared.device, *prepared.store, settings.context)) {
        // Every map came from the cache under the keys of the device the last bake ran on, and
        // this bake runs on another: they are made again under its own.
        prepared.store->restoreCounts(prepared.countsBeforeMaps);
        prepared.directory->clearStaging();
        progress.end();
        return writeBake(prepared, computeMaps(prepared, toolVersion, progress), toolVersion, progress);
    }
    prepared.directory->commit();
    progress.end();

    const double wall = std::chrono::duration<double, std::milli>(Clock::now() - prepared.started).count();
    const auto& input = prepared.input;
    return {.outputDir = settings.outputDir,
            .device = outputs.device,
            .steps = progress.steps(),
            .wallMilliseconds = wall,
            .files = files,
            .shRadiance = outputs.sh.shRadiance,
            .halfRangeClamps = clamps,
            .sanitizedTexels = input.sanitizedTexels,
            .negativeTexels = input.negative,
            .cache = maps.cache,
            .cacheWarnings = outputs.cacheWarnings,
            .compiledKernels = outputs.compiledKernels,
            .pipelineCacheBytes = outputs.pipelineCacheBytes,
            .sceneNotes = prepared.plan.notes,
            .kernelCompileMilliseconds = outputs.kernelCompileMilliseconds,
            .kernelCompiles = outputs.kernelCompiles};
}

BakeSummary bakeEnvironment(const BakeSettings& settings, const std::string& toolVersion, BakeProgress& progress) {
    auto prepared = prepareBake(settings, BakeDestination::Folder, progress);
    auto maps = computeMaps(prepared, toolVersion, progress);
    return writeBake(prepared, std::move(maps), toolVersion, progress);
}

} // namespace iblkit::bake
