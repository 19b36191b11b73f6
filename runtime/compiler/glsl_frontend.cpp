#include "glsl_frontend.hpp"

#include "compile_error.hpp"
#include "glslang_process.hpp"
#include "spirv_tools.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

namespace iblkit::compiler {
std::vector<uint32_t> compileVulkanGlsl(const std::string& source, ShaderStage stage, const std::string& sourceName) {
    initializeGlslangOnce();
    const EShLanguage language = toGlslang(stage);
    glslang::TShader shader(language);
    const char* text = source.c_str();
    const char* name = sourceName.c_str();
    const int length = static_cast<int>(source.size());
    shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
    const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    if (!shader.parse(GetDefaultResources(), 100, false, messages))
        throw CompileError(sourceName + ": error: " + shader.getInfoLog());
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages)) throw CompileError(sourceName + ": error: " + program.getInfoLog());
    std::vector<uint32_t> spirv;
    glslang::GlslangToSpv(*program.getIntermediate(language), spirv);
    validateSpirv(spirv, sourceName);
    return spirv;
}

} // namespace iblkit::compiler
