#pragma once

#include "bake_progress.hpp"
#include "buffer.hpp"
#include "environment_input.hpp"
#include "gpu_steps.hpp"
#include "shading/shading_recipe.hpp"

#include <optional>
#include <vector>

namespace iblkit::render {

// The environment's source cube and what a shading recipe makes of it at the bake's default
// settings, on the device: the maps and lights the split sum reads, the cube the Monte Carlo
// reference reads.
struct BakedMaps {
    vulkan::Image source;   // RGBA32F with its mips, as every bake builds it
    vulkan::Image specular; // the prefiltered cube, by the default method at the recipe's roughness per mip
    vulkan::Image lut;      // the default LUT
    bake::Irradiance irradiance; // of the environment without its lights, where the recipe takes them out
    vulkan::Image lobeTable;     // shading::lobeTable of the recipe's weighting, RGBA32F
    std::vector<shading::EnvironmentLight> lights;
    std::optional<vulkan::Buffer> lightBuffer; // two float4 per light (one of zeros when there is none)
    const shading::ShadingRecipe* recipe = nullptr;
    shading::MipSchedule schedule;
    uint32_t lightLevel = 0; // the first mip prefiltered without the lights
};

// Bakes `input` at the bake's default settings (its cube face size where it is a cube) as `recipe` says.
BakedMaps bakeMaps(const vulkan::VulkanContext& context, const bake::EnvironmentInput& input,
                   const shading::ShadingRecipe& recipe, bake::BakeProgress& progress);

// The environment's mean radiance, in luminance: its maps' (from L00 of the irradiance's SH) and
// its lights', whatever the recipe took out.
double meanLuminance(const BakedMaps& maps);
// The preview's exposure for it: 0.4 / meanLuminance, within the preview's range.
float exposureOf(const BakedMaps& maps);

} // namespace iblkit::render
