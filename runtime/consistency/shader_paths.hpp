#pragma once

#include "compile_options.hpp"
#include "kernels/kernel_table.hpp"
#include "reflection.hpp"

#include <cstdint>
#include <string_view>
#include <vector>

namespace iblkit::consistency {

// The forms of one HLSL shader that must compute the same numbers on Vulkan.
enum class ShaderPath {
    Glslang,          // a. HLSL -> SPIR-V (glslang)
    GlslangOptimized, // b. the same after -O
    GlslRoundTrip,    // c. HLSL -> SPIR-V -> GLSL 450 -> SPIR-V (glslang's GLSL frontend)
    HlslRoundTrip,    // e. HLSL -> SPIR-V -> HLSL (SPIRV-Cross) -> SPIR-V (glslang's HLSL frontend)
};
inline constexpr ShaderPath kVulkanPaths[] = {ShaderPath::Glslang, ShaderPath::GlslangOptimized,
                                              ShaderPath::GlslRoundTrip, ShaderPath::HlslRoundTrip};

std::string_view pathName(ShaderPath path);

using PathProgram = kernels::KernelProgram;

// Compiles the shader the way the path says. Throws compiler::CompileError.
PathProgram compileForPath(ShaderPath path, const compiler::CompileOptions& options);

} // namespace iblkit::consistency
