// iblkit::compileShader as a program calls it: a seed shader in every form, the committed forms
// equal to what the library writes, and errors as iblkit::Error of the right kind, one line each.
#include <iblkit/iblkit.hpp>

#include "read_file.hpp"
#include "register_binding.hpp"
#include "temp_folder.hpp"
#include "thrown_error.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>

namespace iblkit {
namespace {

constexpr uint32_t kSpirvMagic = 0x07230203;

// The documents' prefilter as hlsl/shaders.json compiles it (its folder is always an include folder).
CompileRequest seedPrefilter() {
    CompileRequest request;
    request.source = "hlsl/document/PrefilterSpecularCS.hlsl";
    request.includeDirs = {"hlsl"};
    return request;
}

TEST(CompileApi, TheSeedPrefilterCompilesToEveryForm) {
    const auto result = compileShader(seedPrefilter());
    ASSERT_FALSE(result.spirv.empty());
    EXPECT_EQ(result.spirv[0], kSpirvMagic);
    EXPECT_TRUE(result.refusedForms.empty());
    for (const auto form : {ShaderForm::Glsl, ShaderForm::Essl, ShaderForm::Msl, ShaderForm::Hlsl, ShaderForm::VulkanGlsl,
                            ShaderForm::VulkanEssl}) {
        ASSERT_TRUE(result.forms.count(form)) << shaderFormName(form);
        EXPECT_NE(result.forms.at(form).find("main"), std::string::npos) << shaderFormName(form);
    }
    const auto reflection = nlohmann::json::parse(result.reflectionJson);
    const auto& resources = reflection.at("resources");
    EXPECT_TRUE(std::any_of(resources.begin(), resources.end(), [](const auto& r) { return r.at("name") == "EnvMap"; }))
        << result.reflectionJson;
    EXPECT_TRUE(result.depfile.empty()) << "no depfile unless a target is named";
    const bool includesPbr = std::any_of(result.includedFiles.begin(), result.includedFiles.end(),
                                         [](const auto& file) { return file.filename() == "PBR.fxh"; });
    EXPECT_TRUE(includesPbr);
}

// glsl/ is what the kit's compiler wrote from hlsl/ (tests/compiler checks it fresh): the library's
// forms and reflection are those files, byte for byte.
TEST(CompileApi, TheCommittedFormsAreWhatTheLibraryWrites) {
    auto request = seedPrefilter();
    request.forms = {ShaderForm::Glsl, ShaderForm::Essl, ShaderForm::Msl};
    const auto result = compileShader(request);
    EXPECT_EQ(result.forms.at(ShaderForm::Glsl), testing::readFile("glsl/PrefilterSpecularCS.glsl"));
    EXPECT_EQ(result.forms.at(ShaderForm::Essl), testing::readFile("glsl/PrefilterSpecularCS.essl"));
    EXPECT_EQ(result.forms.at(ShaderForm::Msl), testing::readFile("glsl/PrefilterSpecularCS.metal"));
    EXPECT_EQ(result.reflectionJson, testing::readFile("glsl/PrefilterSpecularCS.json"));
}

TEST(CompileApi, ADepfileNamesTheTargetTheSourceAndItsIncludes) {
    auto request = seedPrefilter();
    request.forms.clear();
    request.depfileTarget = "out/prefilter.spv";
    const auto result = compileShader(request);
    EXPECT_EQ(result.depfile.rfind("out/prefilter.spv: hlsl/document/PrefilterSpecularCS.hlsl", 0), 0u) << result.depfile;
    EXPECT_NE(result.depfile.find("PBR.fxh"), std::string::npos) << result.depfile;
    EXPECT_TRUE(result.forms.empty());
}

TEST(CompileApi, ACompileErrorIsCompileFailedWithItsOneLineMessage) {
    testing::TempFolder scratch;
    CompileRequest request;
    request.source = scratch.write("broken.hlsl", "[numthreads(1, 1, 1)]\nvoid main() {\n    undeclared = 1;\n}\n");
    const auto [kind, message] = testing::errorOf([&] { compileShader(request); });
    EXPECT_EQ(kind, ErrorKind::CompileFailed);
    EXPECT_NE(message.find("broken.hlsl:3:"), std::string::npos) << message;
    EXPECT_NE(message.find("undeclared"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(CompileApi, ABindingShiftPastTheLastBindingIsBadInput) {
    auto request = seedPrefilter();
    request.bindingShifts.unorderedAccess = 70000;
    const auto [kind, message] = testing::errorOf([&] { compileShader(request); });
    EXPECT_EQ(kind, ErrorKind::BadInput);
    EXPECT_EQ(message, "error: binding shift u=70000: bindings end at 65534 (glslang holds them in 16 bits)");
}

TEST(CompileApi, TheDefaultShiftsAreTheBindingRulesAndStagesHaveTheirNames) {
    const compiler::BindingShifts rule;
    const BindingShifts shifts;
    EXPECT_EQ(shifts.constantBuffers, rule.of(compiler::RegisterClass::ConstantBuffer));
    EXPECT_EQ(shifts.shaderResources, rule.of(compiler::RegisterClass::ShaderResource));
    EXPECT_EQ(shifts.samplers, rule.of(compiler::RegisterClass::Sampler));
    EXPECT_EQ(shifts.unorderedAccess, rule.of(compiler::RegisterClass::UnorderedAccess));
    EXPECT_EQ(shaderStageNamed("comp"), ShaderStage::Compute);
    EXPECT_EQ(shaderStageNamed("pixel"), ShaderStage::Fragment);
    EXPECT_EQ(shaderStageNamed("mesh"), std::nullopt);
    EXPECT_EQ(shaderFormName(ShaderForm::VulkanEssl), "vulkan-essl");
}

} // namespace
} // namespace iblkit
