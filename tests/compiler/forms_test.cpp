// Every form is produced, or refused naming the form, the construct and the option that would
// express it: wave operations, ESSL's image access rules, the HLSL round trip's entry point.
#include "compile_error.hpp"
#include "compiler.hpp"
#include "glsl_frontend.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

namespace iblkit::compiler {
namespace {

constexpr const char* kWaveShader = R"(
RWStructuredBuffer<float> Out : register(u0);
[numthreads(32, 1, 1)]
void CSMain(uint3 id : SV_DispatchThreadID) {
    float v = float(id.x);
    Out[id.x] = WaveActiveSum(v) + WavePrefixSum(v) + (WaveIsFirstLane() ? 1 : 0);
}
)";

class Forms : public ::testing::Test {
protected:
    CompiledShader compile(const std::string& text, const std::string& entry = "main") {
        CompileOptions options;
        options.source = folder.write("shader.hlsl", text);
        options.entryPoint = entry;
        return compileShader(options);
    }
    std::string refusal(const CompiledShader& shader, CrossTarget target) {
        try {
            crossCompileShader(shader, target);
        } catch (const CompileError& error) {
            return error.what();
        }
        return "(produced)";
    }
    testing::TempFolder folder;
};

TEST_F(Forms, WaveOperationsInOpenGlFormsNameTheVulkanForm) {
    const auto shader = compile(kWaveShader, "CSMain");
    EXPECT_NE(refusal(shader, CrossTarget::Glsl).find("glsl cannot express the shader: wave operations (Wave*, Quad*) exist "
                                                      "in GLSL only with Vulkan semantics (GL_KHR_shader_subgroup): write "
                                                      "that form with --vulkan-glsl FILE"),
              std::string::npos);
    EXPECT_NE(refusal(shader, CrossTarget::Essl).find("write that form with --vulkan-essl FILE"), std::string::npos);
}

TEST_F(Forms, WaveOperationsGiveVulkanSemanticsGlslThatCompilesBack) {
    const auto shader = compile(kWaveShader, "CSMain");
    for (const auto target : {CrossTarget::VulkanGlsl, CrossTarget::VulkanEssl}) {
        const auto source = crossCompileShader(shader, target).source;
        EXPECT_NE(source.find("#extension GL_KHR_shader_subgroup_arithmetic : require"), std::string::npos) << source;
        EXPECT_NE(source.find("subgroupExclusiveAdd"), std::string::npos) << source; // WavePrefixSum is exclusive
        EXPECT_NO_THROW(compileVulkanGlsl(source, ShaderStage::Compute, "round trip")) << source;
    }
}

// SPIRV-Cross named the HLSL entry point `main`, and could write wave operations only for SM 6.0.
TEST_F(Forms, TheHlslRoundTripKeepsTheEntryPointAndItsWaveOperations) {
    const auto shader = compile(kWaveShader, "CSMain");
    const auto source = crossCompileShader(shader, CrossTarget::Hlsl).source;
    EXPECT_NE(source.find("void CSMain(SPIRV_Cross_Input stage_input)"), std::string::npos) << source;
    CompileOptions again;
    again.source = folder.write("round_trip.hlsl", source);
    again.entryPoint = "CSMain";
    EXPECT_EQ(compileShader(again).reflection.entryPoint, "CSMain");
}

TEST_F(Forms, EsslDeclaresWriteOnlyAndReadOnlyImages) {
    const auto shader = compile(R"(
RWTexture2D<float4> Colour : register(u0);
RWTexture2D<float4> Input : register(u1);
RWTexture2D<float> Depth : register(u2);
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { Colour[id.xy] = Input[id.xy]; Depth[id.xy] = Depth[id.xy] + 1; }
)");
    const auto essl = crossCompileShader(shader, CrossTarget::Essl).source;
    EXPECT_NE(essl.find("rgba32f) uniform writeonly highp image2D Colour;"), std::string::npos) << essl;
    EXPECT_NE(essl.find("rgba32f) uniform readonly highp image2D Input;"), std::string::npos) << essl;
    EXPECT_NE(essl.find("r32f) uniform highp image2D Depth;"), std::string::npos) << essl; // r32f may be both
    EXPECT_NO_THROW(compileOpenGlGlsl(essl, ShaderStage::Compute, "essl")) << essl;
}

TEST_F(Forms, EsslRefusesAnImageReadAndWrittenInAFormatItCannotDoBoth) {
    const auto shader = compile(R"(
RWTexture2D<float4> Colour : register(u0);
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { Colour[id.xy] = Colour[id.xy] * 0.5; }
)");
    EXPECT_NO_THROW(crossCompileShader(shader, CrossTarget::Glsl));
    EXPECT_NE(refusal(shader, CrossTarget::Essl)
                  .find("essl cannot express the shader: storage image 'Colour' (rgba32f) is both read and written, "
                        "which ESSL 3.10 allows only in r32f, r32i and r32ui"),
              std::string::npos);
}

} // namespace
} // namespace iblkit::compiler
