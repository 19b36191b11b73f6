#include "glsl_frontend.hpp"

#include "compile_error.hpp"
#include "glslang_process.hpp"
#include "spirv_tools.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

namespace iblkit::compiler {
namespace {

std::vector<uint32_t> compileGlsl(const std::string& source, ShaderStage stage, const std::string& sourceName, bool vulkan) {
    initializeGlslangOnce();
    const EShLanguage language = toGlslang(stage);
    glslang::TShader shader(language);
    const char* text = source.c_str();
    const char* name = sourceName.c_str();
    const int length = static_cast<int>(source.size());
    shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
    const auto client = vulkan ? glslang::EShClientVulkan : glslang::EShClientOpenGL;
    shader.setEnvInput(glslang::EShSourceGlsl, language, client, 100);
    if (vulkan) shader.setEnvClient(client, glslang::EShTargetVulkan_1_1);
    else shader.setEnvClient(client, glslang::EShTargetOpenGL_450);
    shader.setEnvTarget(glslang::EShTargetSpv, vulkan ? glslang::EShTargetSpv_1_3 : glslang::EShTargetSpv_1_0);
    // An OpenGL driver compiling GLSL gives a plain uniform (a push-constant block's OpenGL form)
    // its location itself; SPIR-V for OpenGL (ARB_gl_spirv) needs one written.
    if (!vulkan) shader.setAutoMapLocations(true);
    const auto messages = static_cast<EShMessages>(vulkan ? EShMsgSpvRules | EShMsgVulkanRules : EShMsgSpvRules);
    if (!shader.parse(GetDefaultResources(), 100, false, messages))
        throw CompileError(sourceName + ": error: " + shader.getInfoLog());
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages)) throw CompileError(sourceName + ": error: " + program.getInfoLog());
    std::vector<uint32_t> spirv;
    glslang::GlslangToSpv(*program.getIntermediate(language), spirv);
    validateSpirv(spirv, sourceName, vulkan ? SpirvEnvironment::Vulkan11 : SpirvEnvironment::OpenGl45);
    return spirv;
}

} // namespace

std::vector<uint32_t> compileVulkanGlsl(const std::string& source, ShaderStage stage, const std::string& sourceName) {
    return compileGlsl(source, stage, sourceName, true);
}

std::vector<uint32_t> compileOpenGlGlsl(const std::string& source, ShaderStage stage, const std::string& sourceName) {
    return compileGlsl(source, stage, sourceName, false);
}

} // namespace iblkit::compiler
