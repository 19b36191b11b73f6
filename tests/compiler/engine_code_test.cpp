// What engines write that glslang alone does not take, compiled by the kit: the forms are read
// back before they are written (ESSL at the version a construct needs), NonUniformResourceIndex,
// a push-constant block with a register, more registers than the default ranges hold, a texture
// and a sampler on one binding, and source text as Windows keeps it.
#include "compile_error.hpp"
#include "compiler.hpp"
#include "spirv_tools.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace iblkit::compiler {
namespace {

class EngineCode : public ::testing::Test {
protected:
    CompiledShader compile(const std::string& text, const std::string& entry = "main") {
        CompileOptions options;
        options.source = folder.write("shader.hlsl", text);
        options.entryPoint = entry;
        return compileShader(options);
    }
    testing::TempFolder folder;
};

constexpr const char* kCubeArray = R"(
TextureCubeArray<float4> Probes : register(t0);
SamplerState Linear : register(s0);
float4 main(float3 n : NORMAL) : SV_Target { return Probes.Sample(Linear, float4(n, 1.0)); }
)";

TEST_F(EngineCode, EsslIsWrittenAtTheVersionItsConstructsNeed) {
    const auto shader = compile(kCubeArray);
    const auto essl = crossCompileShader(shader, CrossTarget::Essl);
    // ESSL 3.10 has no cube map arrays; 3.20 has them.
    EXPECT_EQ(essl.version, 320u);
    EXPECT_EQ(essl.source.rfind("#version 320 es", 0), 0u) << essl.source.substr(0, 40);
    EXPECT_EQ(crossCompileShader(shader, CrossTarget::Glsl).version, 450u);
    const auto reflection = nlohmann::json::parse(reflectionJson(shader, {{CrossTarget::Essl, essl}}));
    EXPECT_EQ(reflection["form_requirements"]["essl"]["version"], 320);
}

TEST_F(EngineCode, AFormGlslangCannotReadIsRefusedNotWritten) {
    // Non-uniform indexing in OpenGL GLSL needs an NV extension glslang does not have.
    const auto shader = compile(R"(
Texture2D Tiles[] : register(t0);
SamplerState Linear : register(s0);
float4 main(float2 uv : TEXCOORD0, nointerpolation uint i : TEXCOORD1) : SV_Target {
    return Tiles[NonUniformResourceIndex(i)].Sample(Linear, uv);
})");
    try {
        crossCompileShader(shader, CrossTarget::Glsl);
        FAIL() << "written";
    } catch (const CompileError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("glsl cannot express the shader: glslang, its reference compiler, does not read the form"),
                  std::string::npos) << message;
        EXPECT_NE(message.find("\n"), std::string::npos) << "glslang's own words on a second line";
    }
    EXPECT_NE(crossCompileShader(shader, CrossTarget::VulkanGlsl).source.find("nonuniformEXT"), std::string::npos);
}

TEST_F(EngineCode, NonUniformResourceIndexDecoratesTheAccessAndDeclaresItsCapabilities) {
    const auto shader = compile(R"(
Texture2D Tiles[4] : register(t0);
SamplerState Linear : register(s0);
float4 main(float2 uv : TEXCOORD0, nointerpolation uint i : TEXCOORD1) : SV_Target {
    return Tiles[NonUniformResourceIndex(i)].Sample(Linear, uv) + Tiles[2].Sample(Linear, uv);
})");
    const auto text = disassembleSpirv(shader.spirv);
    EXPECT_NE(text.find("OpCapability ShaderNonUniform"), std::string::npos);
    EXPECT_NE(text.find("OpCapability SampledImageArrayNonUniformIndexing"), std::string::npos);
    EXPECT_NE(text.find("OpExtension \"SPV_EXT_descriptor_indexing\""), std::string::npos);
    // The access chain at the run-time index, its load and the sampled image: three at least;
    // the constant index stays uniform.
    size_t decorations = 0;
    for (size_t at = text.find("NonUniform\n"); at != std::string::npos; at = text.find("NonUniform\n", at + 1)) ++decorations;
    EXPECT_GE(decorations, 3u) << text;
    EXPECT_NE(std::find(shader.kitEdits.begin(), shader.kitEdits.end(), "non-uniform-resource-index"), shader.kitEdits.end());
}

TEST_F(EngineCode, APushConstantBlocksRegisterIsIgnoredAsDxcIgnoresIt) {
    const auto shader = compile(R"(
struct Params { float Scale; };
[[vk::push_constant]] ConstantBuffer<Params> g_Params : register(b0, space1);
RWStructuredBuffer<float> Out : register(u0);
[numthreads(1, 1, 1)] void main() { Out[0] = g_Params.Scale; }
)");
    EXPECT_EQ(shader.reflection.pushConstantBlock, "g_Params");
}

TEST_F(EngineCode, MoreRegistersThanTheDefaultRangesMoveTheNextClassesUp) {
    const auto shader = compile(R"(
Texture2D Shadows[40] : register(t9);
SamplerState Linear : register(s0);
RWStructuredBuffer<float> Out : register(u0);
[numthreads(1, 1, 1)] void main() { Out[0] = Shadows[39].SampleLevel(Linear, 0.5, 0).x; }
)");
    // t holds 9 + 40 = 49 registers: its range grows to 64, and s and u move up by 32.
    EXPECT_EQ(shader.bindingShifts.of(RegisterClass::ShaderResource), 32u);
    EXPECT_EQ(shader.bindingShifts.of(RegisterClass::Sampler), 96u);
    EXPECT_EQ(shader.bindingShifts.of(RegisterClass::UnorderedAccess), 128u);
}

TEST_F(EngineCode, ShiftsTheUserGaveAreNeverMoved) {
    CompileOptions options;
    options.source = folder.write("shader.hlsl", "Texture2D Shadows[40] : register(t9);\nRWStructuredBuffer<float> Out : register(u0);\n"
                                                 "[numthreads(1, 1, 1)] void main() { Out[0] = Shadows[39].Load(int3(0, 0, 0)).x; }\n");
    options.bindingShifts.set(RegisterClass::UnorderedAccess, 40);
    EXPECT_THROW(compileShader(options), CompileError);
}

TEST_F(EngineCode, ATextureAndASamplerOnOneBindingAreACombinedImageSampler) {
    EXPECT_NO_THROW(compile(R"(
[[vk::binding(1, 0)]] Texture2D Colour;
[[vk::binding(1, 0)]] SamplerState ColourSampler;
float4 main(float2 uv : TEXCOORD0) : SV_Target { return Colour.Sample(ColourSampler, uv); }
)"));
    // Two textures on one binding still clash.
    EXPECT_THROW(compile(R"(
[[vk::binding(1, 0)]] Texture2D A;
[[vk::binding(1, 0)]] Texture2D B;
float4 main() : SV_Target { return A.Load(int3(0, 0, 0)) + B.Load(int3(0, 0, 0)); }
)"),
                 CompileError);
}

TEST_F(EngineCode, SourceTextAsWindowsKeepsIt) {
    folder.write("Include/Helpers.hlsli", "float Twice(float x) { return 2.0 * x; }"); // no last newline
    const auto shader = compile("\xEF\xBB\xBF" "RWStructuredBuffer<float> Out : register(u0);\r\n"
                                "#include \"include\\\\HELPERS.hlsli\"\r\n"
                                "[numthreads(1, 1, 1)] void main() { Out[0] = Twice(1.0); }");
    EXPECT_EQ(shader.includedFiles.size(), 1u);
}

} // namespace
} // namespace iblkit::compiler
