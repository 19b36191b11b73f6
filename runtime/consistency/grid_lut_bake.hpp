#pragma once

#include "gl_bake.hpp"
#include "shader_paths.hpp"
#include "context_options.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace iblkit::consistency {

// The quadrature-grid LUT's two kernels, each on its own: BrdfLutGridCS's nodes of a gridSize²
// grid ((scale, bias) per node, row by row), and BrdfLutResampleCS's size² LUT from the given
// grid, on a Vulkan path and on OpenGL.
std::vector<float> gpuBrdfLutGrid(const vulkan::VulkanContext& context, const PathProgram& program, uint32_t gridSize);
std::vector<float> gpuBrdfLutResample(const vulkan::VulkanContext& context, const PathProgram& program,
                                      std::span<const float> grid, uint32_t gridSize, uint32_t size);
std::vector<float> glBrdfLutGrid(const opengl::EglContext& context, const OpenGlForm& form, uint32_t gridSize);
std::vector<float> glBrdfLutResample(const opengl::EglContext& context, const OpenGlForm& form,
                                     std::span<const float> grid, uint32_t gridSize, uint32_t size);

} // namespace iblkit::consistency
