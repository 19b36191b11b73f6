#pragma once

#include "buffer.hpp"
#include "kernels/kernel_steps.hpp"
#include "shader_paths.hpp"
#include "suite_inputs.hpp"
#include "vulkan_context.hpp"

#include <glm/vec4.hpp>

#include <functional>
#include <span>
#include <vector>

namespace iblkit::consistency {

// The kit's cube kernels on Vulkan, each through its kernels::run* step; cube results are RGBA
// per texel, ordered face, row, column (mip by mip for the chain).

// SkyCube: the built-in environment onto a size x size cube.
std::vector<float> gpuSkyCube(const vulkan::VulkanContext& context, const PathProgram& program, uint32_t size,
                              uint32_t supersample);
// EquirectToCube: the panorama onto mip 0 of a size x size cube.
std::vector<float> gpuEquirectToCube(const vulkan::VulkanContext& context, const PathProgram& program,
                                     const Panorama& panorama, uint32_t size, uint32_t supersample);

// DownsampleCube: mips 1 to 1x1 of a cube whose mip 0 is `cube`'s, one after the other.
std::vector<float> gpuDownsampleChain(const vulkan::VulkanContext& context, const PathProgram& program,
                                      const MippedCube& cube);

// ShProject: one mip of `cube` (uploaded with all its mips) on the 9 harmonics.
kernels::ShProjection gpuShProject(const vulkan::VulkanContext& context, const PathProgram& program,
                                   const MippedCube& cube, uint32_t mip);

// IrradianceCube: an outSize cube from a momentSize cube of moments (reference::irradianceMoments).
std::vector<float> gpuIrradianceCube(const vulkan::VulkanContext& context, const PathProgram& program,
                                     const std::vector<float>& moments, uint32_t momentSize, uint32_t outSize);

// Prefilter of a method that reads the source's mips (PrefilterFilteredCS, PrefilterPyramidCS,
// PrefilterRingCS): `cube` with its whole chain as EnvMap, read through a trilinear sampler,
// into size x size faces; `dispatch` runs the kernel's step (kernel_steps.hpp) into mip 0.
using MippedDispatch = std::function<void(kernels::Kernel& kernel, vulkan::Image& envMap, const vulkan::Sampler& sampler,
                                          vulkan::Image& prefiltered)>;
std::vector<float> gpuMippedPrefilter(const vulkan::VulkanContext& context, const PathProgram& program,
                                      const MippedCube& cube, uint32_t size, const MippedDispatch& dispatch);
// PrefilterTable: the same, each texel summing `table`'s samples.
std::vector<float> gpuTablePrefilter(const vulkan::VulkanContext& context, const PathProgram& program,
                                     const MippedCube& cube, std::span<const glm::vec4> table, uint32_t size);
// The maps PreviewCS and SplitSumSpheresCS shade with, uploaded: Specular, IrradianceMap, BrdfLut.
struct GpuShadingMaps {
    vulkan::Image specular, irradiance, lut, lobeTable;
    vulkan::Buffer lights;
};
GpuShadingMaps uploadShadingMaps(const vulkan::VulkanContext& context, const PreviewInputs& inputs);

// Preview: the RGBA image, row by row.
std::vector<float> gpuPreview(const vulkan::VulkanContext& context, const PathProgram& program,
                              const PreviewInputs& inputs);

} // namespace iblkit::consistency
