#pragma once

#include "bake_progress.hpp"
#include "buffer.hpp"
#include "image.hpp"
#include "kernels/kernel.hpp"
#include "kernels/kernel_parameters.hpp"
#include "reference_irradiance.hpp"
#include "shading/shading_recipe.hpp"

#include <optional>
#include <vector>

namespace iblkit::bake {

// What a recipe with lights makes of the source cube: the lights, and the environment without
// them (RGBA32F with its mips), which the maps are prefiltered from.
struct TakenOutLights {
    std::vector<shading::EnvironmentLight> lights;
    std::optional<vulkan::Image> residual; // none where no source qualified
    std::vector<reference::CubeTexelRadiance> lightTexels; // of mip 0: the source less the residual, where they differ
    std::vector<float> restMipZero; // mip 0 of the residual, or of the source where no light qualified, on the host
};
TakenOutLights takeOutLights(const vulkan::VulkanContext& context, const vulkan::Image& source,
                             const shading::ExtractionSettings& settings, kernels::Kernel& downsample, BakeProgress& progress);

// IblDiskLight adds each light's diffuse as a disk's; the environment held it in the light's
// texels, whose shape and spread the disk does not have (beside a normal's horizon the two differ
// by percents of E). Adds to each texel of the irradiance cube, computed from the residual, its
// normal's exact irradiance from the light texels less the disks', so that the cube plus the disks
// is the whole environment's irradiance at the cube's texel centres. Where the disks would exceed
// the rest, the texel is clamped at 0.
void addLightTexelsIrradiance(const vulkan::VulkanContext& context, vulkan::Image& irradiance, const TakenOutLights& taken);

// The lobe table of a weighting (shading::builtLobeTable) as an RGBA32F image for the shading to read.
vulkan::Image lobeTableImage(const vulkan::VulkanContext& context, shading::LobeWeighting weighting);

// The glass shading's tables, each computed once per process at its full size where the recipe
// reads it (2 s on two cores each) and at one texel per layer where it does not (the shader
// binds both): shading::transmissionTable as RG32F and shading::sphereTransmissionTable as
// RGBA32F, their layers stacked down.
struct GlassTables {
    vulkan::Image transmission, sphere;
};
const std::vector<float>& transmissionTableOf(uint32_t size);
const std::vector<float>& sphereTransmissionTableOf(uint32_t size);
uint32_t transmissionTableSize(shading::GlassTransmission transmission);
uint32_t sphereTransmissionTableSize(shading::GlassTransmission transmission);
GlassTables glassTables(const vulkan::VulkanContext& context, shading::GlassTransmission transmission);

// Two float4 per light, as Common/ImageBasedLighting.fxh's IblDiskLight reads them (one of zeros
// when there is none: a storage buffer cannot be empty).
std::vector<float> packEnvironmentLights(const std::vector<shading::EnvironmentLight>& lights);
vulkan::Buffer environmentLightBuffer(const vulkan::VulkanContext& context, const std::vector<shading::EnvironmentLight>& lights);

// The IblRecipe fields of a kernel that shades with the maps.
kernels::IblRecipeParameters recipeParameters(const shading::ShadingRecipe& recipe, const shading::MipSchedule& schedule,
                                              size_t lightCount, uint32_t lightLevel);

} // namespace iblkit::bake
