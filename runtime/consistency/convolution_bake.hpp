#pragma once

#include "gl_bake.hpp"
#include "kernels/kernel_steps.hpp"
#include "shader_paths.hpp"
#include "suite_inputs.hpp"
#include "context_options.hpp"

#include <vector>

namespace iblkit::consistency {

// ClusterCubeCS's three pyramids, each a cube half the source's size with every level down to 1x1,
// and the source they were made from (the walk reads its texels as the tree's level 0).
// As wide as the source, its level 0 the source's texels, with holdsSourceTexels (for the walk
// compiled with SOURCE_TEXELS_IN_PYRAMID); else half as wide.
struct PyramidTexels {
    MippedCube source, energy, centroid, geometry;
    std::vector<float> texelSolidAngle; // one face's, row by row
    bool holdsSourceTexels = false;
};

// The convolution method's two kernels, on Vulkan through their kernels::run* steps and on
// OpenGL. A pyramid comes back as its energy, centroid and geometry cubes one after the other,
// each level by level (face, row, column, RGBA).
std::vector<float> gpuClusterPyramid(const vulkan::VulkanContext& context, const PathProgram& program,
                                     const MippedCube& cube);
std::vector<float> glClusterPyramid(const opengl::EglContext& context, const OpenGlForm& form, const MippedCube& cube);

// PrefilterConvolution: an outSize cube from `pyramid`.
std::vector<float> gpuPrefilterConvolution(const vulkan::VulkanContext& context, const PathProgram& program,
                                           const PyramidTexels& pyramid, uint32_t outSize,
                                           const kernels::PrefilterConvolutionParameters& parameters);
std::vector<float> glPrefilterConvolution(const opengl::EglContext& context, const OpenGlForm& form,
                                          const PyramidTexels& pyramid, uint32_t outSize,
                                          const kernels::PrefilterConvolutionParameters& parameters);

} // namespace iblkit::consistency
