#include "shader_paths.hpp"

#include "compiler.hpp"
#include "glsl_frontend.hpp"

namespace iblkit::consistency {

std::string_view pathName(ShaderPath path) {
    switch (path) {
    case ShaderPath::Glslang: return "a. HLSL → SPIR-V (glslang)";
    case ShaderPath::GlslangOptimized: return "b. HLSL → SPIR-V, -O";
    case ShaderPath::GlslRoundTrip: return "c. HLSL → SPIR-V → GLSL 450 → SPIR-V";
    case ShaderPath::HlslRoundTrip: return "e. HLSL → SPIR-V → HLSL → SPIR-V";
    }
    return "?";
}

PathProgram compileForPath(ShaderPath path, const compiler::CompileOptions& options) {
    auto first = options;
    if (path == ShaderPath::GlslangOptimized) first.optimization = compiler::OptimizationLevel::Performance;
    const auto shader = compiler::compileShader(first);
    const std::string name = options.source.string();
    switch (path) {
    case ShaderPath::Glslang:
    case ShaderPath::GlslangOptimized: return {shader.spirv, shader.reflection};
    case ShaderPath::GlslRoundTrip: {
        const auto glsl = compiler::crossCompileShader(shader, compiler::CrossTarget::VulkanGlsl).source;
        const auto spirv = compiler::compileVulkanGlsl(glsl, shader.reflection.stage, name + " (GLSL)");
        return {spirv, compiler::reflectSpirv(spirv, "main", name + " (GLSL)")};
    }
    case ShaderPath::HlslRoundTrip: {
        auto again = options;
        again.sourceText = compiler::crossCompileShader(shader, compiler::CrossTarget::Hlsl).source;
        again.entryPoint = "main";
        again.defines.clear(); // already applied
        const auto roundTrip = compiler::compileShader(again);
        return {roundTrip.spirv, roundTrip.reflection};
    }
    }
    return {};
}

} // namespace iblkit::consistency
