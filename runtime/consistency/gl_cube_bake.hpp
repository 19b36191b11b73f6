#pragma once

#include "gl_bake.hpp"
#include "gl_object.hpp"
#include "kernels/kernel_steps.hpp"
#include "suite_inputs.hpp"

#include <glm/vec4.hpp>

#include <span>
#include <vector>

namespace iblkit::consistency {

// The same runs as gpu_cube_bake's, as OpenGL 4.5 compute shaders: a cube is a
// GL_TEXTURE_2D_ARRAY of 6 layers (what the GLSL form's sampler2DArray and image2DArray take),
// a TextureCube a GL_TEXTURE_CUBE_MAP.
std::vector<float> glSkyCube(const opengl::EglContext& context, const OpenGlForm& form, uint32_t size, uint32_t supersample);
std::vector<float> glEquirectToCube(const opengl::EglContext& context, const OpenGlForm& form, const Panorama& panorama,
                                    uint32_t size, uint32_t supersample);
std::vector<float> glDownsampleChain(const opengl::EglContext& context, const OpenGlForm& form, const MippedCube& cube);
kernels::ShProjection glShProject(const opengl::EglContext& context, const OpenGlForm& form, const MippedCube& cube,
                                  uint32_t mip);
std::vector<float> glIrradianceCube(const opengl::EglContext& context, const OpenGlForm& form,
                                    const std::vector<float>& moments, uint32_t momentSize, uint32_t outSize);
// A prefilter that reads `cube`'s whole chain (PrefilterFilteredCS, PrefilterPyramidCS,
// PrefilterRingCS), its cbuffer set to `parameters`.
std::vector<float> glMippedPrefilter(const opengl::EglContext& context, const OpenGlForm& form, const MippedCube& cube,
                                     const kernels::NamedValues& parameters, uint32_t size);
std::vector<float> glTablePrefilter(const opengl::EglContext& context, const OpenGlForm& form, const MippedCube& cube,
                                    std::span<const glm::vec4> table, uint32_t size);
// The maps PreviewCS and SplitSumSpheresCS shade with, bound to Specular, IrradianceMap and BrdfLut
// with the linear clamp sampler; kept alive while the shader runs.
struct GlShadingMaps {
    opengl::GlObject specular, irradiance, lut, lobeTable, sampler, lights;
};
GlShadingMaps bindShadingMaps(const opengl::EglContext& context, const OpenGlForm& form, const PreviewInputs& inputs);

std::vector<float> glPreview(const opengl::EglContext& context, const OpenGlForm& form, const PreviewInputs& inputs);

} // namespace iblkit::consistency
