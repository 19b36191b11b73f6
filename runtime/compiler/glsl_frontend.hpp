#pragma once

#include "shader_stage.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::compiler {

// GLSL (with Vulkan semantics) -> SPIR-V for Vulkan 1.1 with glslang's GLSL frontend, validated:
// how the consistency suite turns the cross-compiled GLSL back into something to run.
// Throws CompileError with glslang's messages.
std::vector<uint32_t> compileVulkanGlsl(const std::string& source, ShaderStage stage, const std::string& sourceName);

// GLSL 450 or ESSL 310 for OpenGL -> SPIR-V for OpenGL 4.5 (ARB_gl_spirv), validated: how the
// OpenGL forms are read back. Throws CompileError with glslang's messages.
std::vector<uint32_t> compileOpenGlGlsl(const std::string& source, ShaderStage stage, const std::string& sourceName);

} // namespace iblkit::compiler
