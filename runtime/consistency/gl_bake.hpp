#pragma once

#include "compile_options.hpp"
#include "cross_compile.hpp"
#include "cube_environment.hpp"
#include "egl_context.hpp"

#include <array>
#include <vector>

namespace iblkit::consistency {

// d. HLSL -> SPIR-V -> GLSL 450 (the form committed in glsl/), with the bindings the compiler
// recorded for it and the shader's workgroup size.
struct OpenGlForm {
    compiler::CrossCompiled glsl;
    std::array<uint32_t, 3> workgroupSize;
};
OpenGlForm openGlForm(const compiler::CompileOptions& options);

// The same runs as gpu_bake's, as OpenGL 4.5 compute shaders (RG32F and RGBA32F images).
std::vector<float> glBrdfLut(const opengl::EglContext& context, const OpenGlForm& form, uint32_t size);
std::vector<float> glPrefilter(const opengl::EglContext& context, const OpenGlForm& form,
                               const reference::CubeEnvironment& environment, float roughness, uint32_t size);

} // namespace iblkit::consistency
