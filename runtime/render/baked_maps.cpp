#include "render/baked_maps.hpp"

#include "bake_kernels.hpp"
#include "bake_settings.hpp"
#include "baked_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>

namespace iblkit::render {
namespace {

std::vector<float> mipZero(const vulkan::VulkanContext& context, const vulkan::Image& cube) {
    const auto values = cube.download(context);
    const auto first = values.begin() + std::ptrdiff_t(cube.valueOffset(0, 0));
    const size_t count = size_t(6) * cube.desc().width * cube.desc().width * 4;
    return {first, first + std::ptrdiff_t(count)};
}

// The table depends on the weighting alone: computed once per process (48 ms), not once per bake.
const std::vector<float>& lobeTableOf(shading::LobeWeighting weighting) {
    static std::mutex mutex;
    static std::map<shading::LobeWeighting, std::vector<float>> tables;
    const std::lock_guard lock(mutex);
    auto found = tables.find(weighting);
    if (found == tables.end()) found = tables.emplace(weighting, shading::lobeTable(shading::kLobeTableSize, weighting)).first;
    return found->second;
}

vulkan::Image lobeTableImage(const vulkan::VulkanContext& context, shading::LobeWeighting weighting) {
    const uint32_t size = shading::kLobeTableSize;
    vulkan::Image table(context, {"LobeTable", &vulkan::texelFormatNamed("R32G32B32A32_SFLOAT"), size, size, 1, 1, false, false});
    table.upload(context, lobeTableOf(weighting));
    return table;
}

} // namespace

double meanLuminance(const BakedMaps& maps) {
    double mean = bake::meanLuminance(maps.irradiance.sh);
    for (const auto& light : maps.lights)
        mean += (0.2126 * light.radiance.r + 0.7152 * light.radiance.g + 0.0722 * light.radiance.b) * light.solidAngle /
                (4 * std::numbers::pi);
    return mean;
}

float exposureOf(const BakedMaps& maps) {
    const double mean = meanLuminance(maps);
    if (!(mean > 0) || !std::isfinite(mean)) return 1.f;
    return float(std::clamp(0.4 / mean, bake::kMinPreviewExposure, bake::kMaxPreviewExposure));
}

std::vector<float> packEnvironmentLights(const std::vector<shading::EnvironmentLight>& lights) {
    std::vector<float> values;
    for (const auto& light : lights)
        values.insert(values.end(), {float(light.direction.x), float(light.direction.y), float(light.direction.z),
                                     float(light.angularRadius), float(light.radiance.r), float(light.radiance.g),
                                     float(light.radiance.b), float(light.solidAngle)});
    if (values.empty()) values.assign(8, 0.f);
    return values;
}

BakedMaps bakeMaps(const vulkan::VulkanContext& context, const bake::EnvironmentInput& input,
                   const shading::ShadingRecipe& recipe, bake::BakeProgress& progress) {
    bake::BakeSettings defaults;
    bake::BakeKernels kernels(context, defaults);
    const uint32_t size = bake::resolvedSize(defaults, input.cubeSize);
    auto source = bake::buildSourceCube(context, input, size, progress);
    const uint32_t mips = bake::resolvedMips(defaults, size);
    const auto schedule = shading::scheduleOf(recipe, mips, size);
    std::vector<shading::EnvironmentLight> lights;
    std::optional<vulkan::Image> residual;
    if (recipe.lights) {
        progress.begin("lights");
        auto extraction = shading::extractLights(mipZero(context, source), size, *recipe.lights);
        progress.end();
        lights = std::move(extraction.lights);
        if (!lights.empty()) {
            bake::EnvironmentInput faces;
            faces.kind = bake::InputKind::Cube;
            faces.cubeSize = size;
            faces.cubeTexels = std::move(extraction.residual);
            residual.emplace(bake::buildSourceCube(context, faces, size, progress));
        }
    }
    const uint32_t lightLevel = shading::lightLevelOf(recipe, schedule, lights);
    bake::SpecularLevels levels{{}, {}, residual ? &*residual : nullptr, lightLevel};
    for (uint32_t mip = 0; mip < mips; ++mip) levels.roughness.push_back(float(schedule.roughnessOf(mip)));
    auto& prefilter = *kernels.specular();
    prefilter.setWeighting(recipe.weighting);
    auto specular = bake::prefilterLevels(context, source, levels, &prefilter, progress);
    auto lut = bake::integrateBrdfLut(context, defaults.lutSize, *kernels.lut(), progress);
    auto irradiance = bake::computeIrradiance(context, kernels.irradiance(), residual ? *residual : source,
                                              defaults.irradianceSize, progress, true, recipe.irradianceSource);
    const auto packed = packEnvironmentLights(lights);
    return {std::move(source),
            std::move(specular),
            std::move(lut),
            std::move(irradiance),
            lobeTableImage(context, recipe.weighting),
            std::move(lights),
            vulkan::storageBuffer(context, std::as_bytes(std::span(packed)), "Lights"),
            &recipe,
            schedule,
            lightLevel};
}

} // namespace iblkit::render
