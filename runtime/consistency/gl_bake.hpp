#pragma once

#include "compile_options.hpp"
#include "cross_compile.hpp"
#include "cube_environment.hpp"
#include "egl_context.hpp"
#include "reflection.hpp"

#include <array>
#include <string>
#include <vector>

namespace iblkit::consistency {

// d. HLSL -> SPIR-V -> GLSL 450 (the form committed in glsl/), with the bindings the compiler
// recorded for it, the shader's workgroup size and the reflection of its cbuffer.
struct OpenGlForm {
    std::string name;
    compiler::CrossCompiled glsl;
    std::array<uint32_t, 3> workgroupSize;
    compiler::ShaderReflection reflection;
};
OpenGlForm openGlForm(const compiler::CompileOptions& options);

// The same runs as gpu_bake's, as OpenGL 4.5 compute shaders (RG32F and RGBA32F images).
std::vector<float> glBrdfLut(const opengl::EglContext& context, const OpenGlForm& form, uint32_t size);
std::vector<float> glPrefilter(const opengl::EglContext& context, const OpenGlForm& form,
                               const reference::CubeEnvironment& environment, float roughness, uint32_t size);
std::vector<float> glBrdfLutChunks(const opengl::EglContext& context, const OpenGlForm& form, uint32_t size,
                                   uint32_t samples, uint32_t chunk);
std::vector<float> glPrefilterChunks(const opengl::EglContext& context, const OpenGlForm& form,
                                     const reference::CubeEnvironment& environment, float roughness, uint32_t size,
                                     uint32_t samples, uint32_t chunk);

} // namespace iblkit::consistency
