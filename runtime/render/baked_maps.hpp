#pragma once

#include "bake_progress.hpp"
#include "environment_input.hpp"
#include "gpu_steps.hpp"

namespace iblkit::render {

// The environment's source cube and what the bake's defaults make of it, on the device: the maps
// the split sum reads, the cube the Monte Carlo reference reads.
struct BakedMaps {
    vulkan::Image source;   // RGBA32F with its mips, as every bake builds it
    vulkan::Image specular; // the prefiltered cube, the default method
    vulkan::Image lut;      // the default LUT
    bake::Irradiance irradiance;
};

// Bakes `input` at the bake's default settings (its cube face size where it is a cube).
BakedMaps bakeMaps(const vulkan::VulkanContext& context, const bake::EnvironmentInput& input, bake::BakeProgress& progress);

} // namespace iblkit::render
