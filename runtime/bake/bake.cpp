#include "bake.hpp"

#include "bake_directory.hpp"
#include "baked_outputs.hpp"
#include "bake_error.hpp"
#include "bake_manifest.hpp"
#include "bake_plan.hpp"
#include "environment_input.hpp"
#include "lights_gltf.hpp"
#include "shading_maps.hpp"
#include "content_store.hpp"
#include "profiles/cube_frame.hpp"

#include <fmt/core.h>

#include <bit>
#include <chrono>

namespace iblkit::bake {

using Clock = std::chrono::steady_clock;

BakeSummary bakeEnvironment(const BakeSettings& settings, const std::string& toolVersion, BakeProgress& progress) {
    const auto started = Clock::now();
    validateSettings(settings);
    // A scene that cannot be read fails before any device work.
    const auto scene = settings.scene ? std::optional(scene::readSceneMaterials(*settings.scene)) : std::nullopt;
    BakeDirectory directory(settings.outputDir, settings.environment);

    progress.begin("load");
    const auto input = loadEnvironment(settings.environment, {settings.sanitize, settings.strict});
    const uint32_t size = resolvedSize(settings, input.cubeSize);
    if (!std::has_single_bit(size))
        throw BakeError(fmt::format("the input cube's faces are {}x{}; the bake needs a power of two", size, size));
    const uint32_t mips = resolvedMips(settings, size);
    const auto plan = planBake(settings, size, scene);
    progress.end();

    std::optional<cache::ContentStore> store;
    if (settings.cache) store.emplace(*settings.cache);
    auto outputs = bakeOutputs(settings, input, size, plan, toolVersion, progress, store ? &*store : nullptr);

    progress.begin("write");
    const bool lobeTableFile = outputs.lobeTable.has_value();
    const ManifestFacts facts{toolVersion, outputs.device, &input, &settings, size, mips, &outputs.sh, nullptr,
                              outputs.previewExposure, &plan, &outputs.lights, outputs.lightLevel, lobeTableFile};
    if (outputs.specular) outputs.specular->keyValues["iblkit.shading"] = shadingJson(facts).dump();
    std::vector<BakedTexture> textures; // what the plan needs: a skipped output is no file
    for (auto* texture : {&outputs.specular, &outputs.lut, &outputs.irradiance, &outputs.lobeTable})
        if (*texture) textures.push_back(std::move(**texture));
    const auto& profile = resolvedProfile(settings);
    for (auto& texture : textures)
        if (texture.faces == 6)
            profiles::arrangeCube(profile.frame, texture.values, texture.size, texture.mips, image_io::channelCount(texture.format));
    std::vector<HalfRangeClamp> clamps;
    for (auto& texture : textures)
        if (auto clamp = applyHalfRangePolicy(texture, settings.strict)) clamps.push_back(std::move(*clamp));
    const std::string writer = "iblkit " + toolVersion;
    std::vector<WrittenFile> files;
    for (const auto& texture : textures)
        for (auto& file : writeTexture(directory.staging(), texture, settings, writer)) files.push_back(std::move(file));
    files.push_back(writeBytes(directory.staging(), "preview.png", std::as_bytes(std::span(outputs.previewPng))));
    if (!outputs.lights.empty()) {
        const auto gltf = lightsGltf(outputs.lights, writer);
        files.push_back(writeBytes(directory.staging(), "lights.gltf", std::as_bytes(std::span(gltf))));
    }

    auto manifestFacts = facts;
    manifestFacts.halfRangeClamps = &clamps;
    auto manifest = bakeManifest(manifestFacts);
    manifest["files"] = filesJson(files);
    const std::string manifestText = manifest.dump(2) + "\n";
    files.push_back(writeBytes(directory.staging(), "manifest.json", std::as_bytes(std::span(manifestText))));
    directory.commit();
    progress.end();

    const double wall = std::chrono::duration<double, std::milli>(Clock::now() - started).count();
    BakeSummary summary{settings.outputDir, outputs.device, progress.steps(), wall, files,
                        outputs.sh.shRadiance, clamps, input.sanitizedTexels, input.negative, {}, outputs.cacheWarnings,
                        outputs.compiledKernels, outputs.pipelineCacheBytes};
    if (store && !settings.context.validation) summary.cache = store->counts();
    return summary;
}

} // namespace iblkit::bake
