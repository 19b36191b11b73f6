#include "render/baked_maps.hpp"

#include "bake_kernels.hpp"
#include "bake_settings.hpp"
#include "baked_outputs.hpp"
#include "shading_maps.hpp"

#include "profiles/engine_profile.hpp"

namespace iblkit::render {

double meanLuminance(const BakedMaps& maps) { return bake::meanLuminance(maps.irradiance.sh, maps.lights); }

float exposureOf(const BakedMaps& maps) { return bake::previewExposure(maps.irradiance.sh, maps.lights); }

BakedMaps bakeMaps(const vulkan::VulkanContext& context, const bake::EnvironmentInput& input,
                   const shading::ShadingRecipe& recipe, bake::BakeProgress& progress) {
    bake::BakeSettings asked;
    asked.profile = profiles::profileMadeFor(recipe.name).name;
    auto defaults = bake::resolveSettings(asked);
    bake::resolveFaceSize(defaults, input.cubeSize);
    bake::BakeKernels kernels(context, defaults);
    const uint32_t size = defaults.faceSize, mips = defaults.mipCount;
    auto source = bake::buildSourceCube(context, input, size, progress);
    const auto schedule = shading::scheduleOf(recipe, mips, size);
    bake::TakenOutLights taken;
    if (recipe.lights) taken = bake::takeOutLights(context, source, *recipe.lights, kernels.downsample(), progress);
    auto& lights = taken.lights;
    auto& residual = taken.residual;
    const uint32_t lightLevel = shading::lightLevelOf(recipe, schedule, lights);
    const bake::SpecularLevels levels{bake::roughnessOfMips(recipe, mips, size), {}, residual ? &*residual : nullptr, lightLevel};
    auto& prefilter = *kernels.specular();
    prefilter.setWeighting(recipe.weighting);
    auto specular = bake::prefilterLevels(context, source, levels, &prefilter, progress);
    auto lut = bake::integrateBrdfLut(context, defaults.lutSize, *kernels.lut(), progress);
    auto irradiance = bake::computeIrradiance(context, kernels.irradiance(), {residual ? *residual : source, taken.restMipZero},
                                              defaults.irradianceSize, progress, true, recipe.irradianceSource);
    bake::addLightTexelsIrradiance(context, irradiance.cube, taken);
    auto lightBuffer = bake::environmentLightBuffer(context, lights);
    return {std::move(source),
            std::move(specular),
            std::move(lut),
            std::move(irradiance),
            bake::lobeTableImage(context, recipe.weighting),
            std::move(lights),
            std::move(lightBuffer),
            &recipe,
            schedule,
            lightLevel};
}

} // namespace iblkit::render
