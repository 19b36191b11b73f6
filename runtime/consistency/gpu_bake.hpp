#pragma once

#include "cube_environment.hpp"
#include "shader_paths.hpp"
#include "vulkan_context.hpp"

#include <vector>

namespace iblkit::consistency {

// Runs a LUT program (its storage image must be R32G32_SFLOAT) over size x size and reads it
// back: (scale, bias) per texel, row by row.
std::vector<float> gpuBrdfLut(const vulkan::VulkanContext& context, const PathProgram& program, uint32_t size);

// Runs a prefilter program (storage image R32G32B32A32_SFLOAT) over size x size faces for one
// roughness, sampling the environment's mip 0 linearly; RGBA per texel, face by face.
std::vector<float> gpuPrefilter(const vulkan::VulkanContext& context, const PathProgram& program,
                                const reference::CubeEnvironment& environment, float roughness, uint32_t size);

// The chunked twins of both: `samples` (the program's SAMPLE_COUNT) in dispatches of `chunk`
// samples through an accumulator image, the last dispatch writing the result.
std::vector<float> gpuBrdfLutChunks(const vulkan::VulkanContext& context, const PathProgram& program, uint32_t size,
                                    uint32_t samples, uint32_t chunk);
std::vector<float> gpuPrefilterChunks(const vulkan::VulkanContext& context, const PathProgram& program,
                                      const reference::CubeEnvironment& environment, float roughness, uint32_t size,
                                      uint32_t samples, uint32_t chunk);

} // namespace iblkit::consistency
