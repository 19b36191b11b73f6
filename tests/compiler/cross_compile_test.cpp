// Every generated form is usable: GLSL and ESSL compile back to valid SPIR-V, the HLSL
// round trip compiles again with the same registers, and each target's bindings are recorded.
#include "compile_error.hpp"
#include "compiler.hpp"
#include "glsl_frontend.hpp"
#include "hlsl_matrix_loads.hpp"
#include "seed_test_support.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

namespace iblkit::compiler {
namespace {

const TargetBinding* findBinding(const CrossCompiled& compiled, const std::string& resource) {
    for (const auto& binding : compiled.bindings)
        if (binding.resource == resource) return &binding;
    return nullptr;
}

class EveryShaderAndOptimization : public ::testing::TestWithParam<std::tuple<std::string, OptimizationLevel>> {
protected:
    CompileOptions options() const { return testing::manifestShader(std::get<0>(GetParam())).options; }
    CompiledShader compile() const {
        auto options = this->options();
        options.optimization = std::get<1>(GetParam());
        return compileShader(options);
    }
};

TEST_P(EveryShaderAndOptimization, GlslAndEsslCompileBackToValidSpirv) {
    const auto shader = compile();
    for (auto target : {CrossTarget::Glsl, CrossTarget::Essl}) {
        const auto compiled = crossCompileShader(shader, target);
        EXPECT_NO_THROW(compileOpenGlGlsl(compiled.source, ShaderStage::Compute, "form")) << crossTargetName(target) << ":\n" << compiled.source;
    }
}

TEST_P(EveryShaderAndOptimization, HlslRoundTripCompilesAgainWithTheSameRegisters) {
    const auto shader = compile();
    testing::TempFolder folder;
    CompileOptions again;
    again.source = folder.write("round_trip.hlsl", crossCompileShader(shader, CrossTarget::Hlsl).source);
    // HLSL cannot state a storage format (Direct3D takes it from the view), so the round trip
    // needs the same --image-format as the original.
    again.imageFormats = options().imageFormats;
    const auto roundTrip = compileShader(again);
    ASSERT_EQ(roundTrip.reflection.resources.size(), shader.reflection.resources.size());
    for (const auto& resource : shader.reflection.resources) {
        const auto* same = roundTrip.reflection.find(resource.name);
        ASSERT_NE(same, nullptr) << resource.name;
        EXPECT_EQ(same->location.registerName(), resource.location.registerName()) << resource.name;
        EXPECT_EQ(same->location.binding, resource.location.binding) << resource.name;
        EXPECT_EQ(same->format, resource.format) << resource.name;
    }
    EXPECT_EQ(roundTrip.reflection.workgroupSize, shader.reflection.workgroupSize);
}

INSTANTIATE_TEST_SUITE_P(SeedShaders, EveryShaderAndOptimization,
                         ::testing::Combine(::testing::Values("PrecomputedBrdfCS", "PrefilterSpecularCS"),
                                            ::testing::Values(OptimizationLevel::None, OptimizationLevel::Performance)),
                         [](const auto& info) {
                             return std::get<0>(info.param) +
                                    (std::get<1>(info.param) == OptimizationLevel::None ? "" : "_O");
                         });

TEST(OpenGlForms, TextureAndSamplerBecomeOneCombinedSamplerOnATextureUnit) {
    const auto shader = testing::compileSeed("PrefilterSpecularCS");
    const auto glsl = crossCompileShader(shader, CrossTarget::Glsl);
    const auto* combined = findBinding(glsl, "EnvMap+EnvMapSampler");
    ASSERT_NE(combined, nullptr);
    EXPECT_EQ(combined->namespace_, "texture_unit");
    EXPECT_EQ(combined->slot, 0u);
    EXPECT_EQ(combined->declaredName, "EnvMap_EnvMapSampler");
    EXPECT_NE(glsl.source.find("layout(binding = 0) uniform samplerCube EnvMap_EnvMapSampler;"), std::string::npos)
        << glsl.source;
    EXPECT_EQ(findBinding(glsl, "PrefilterSpecularParameter")->namespace_, "uniform_block");
    EXPECT_EQ(findBinding(glsl, "Prefiltered")->namespace_, "image_unit");
    EXPECT_EQ(glsl.source.find("set ="), std::string::npos) << "OpenGL has no descriptor sets";
    EXPECT_EQ(glsl.source.rfind("#version 450", 0), 0u);
}

TEST(OpenGlForms, EsslDeclaresTheLutWithAFourChannelStandIn) {
    const auto essl = crossCompileShader(testing::compileSeed("PrecomputedBrdfCS"), CrossTarget::Essl);
    const auto* lut = findBinding(essl, "Precomputed");
    ASSERT_NE(lut, nullptr);
    EXPECT_EQ(lut->format, "rgba16f");
    EXPECT_EQ(lut->adaptedFrom, "rg16f");
    EXPECT_NE(essl.source.find("rgba16f) uniform writeonly highp image2D Precomputed"), std::string::npos) << essl.source;
    const auto glsl = crossCompileShader(testing::compileSeed("PrecomputedBrdfCS"), CrossTarget::Glsl);
    EXPECT_EQ(findBinding(glsl, "Precomputed")->format, "rg16f") << "desktop GLSL keeps the real format";
}

TEST(OpenGlForms, EsslRefusesAFormatWithoutAStandIn) {
    testing::TempFolder folder;
    CompileOptions options;
    options.source = folder.write("unorm16.hlsl", R"(
RWTexture2D<float4> Target;
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { Target[id.xy] = float4(1, 0, 0, 1); }
)");
    options.imageFormats["Target"] = "rgba16";
    const auto shader = compileShader(options);
    EXPECT_NO_THROW(crossCompileShader(shader, CrossTarget::Glsl));
    try {
        crossCompileShader(shader, CrossTarget::Essl);
        FAIL() << "expected CompileError";
    } catch (const CompileError& error) {
        EXPECT_NE(std::string(error.what()).find("ESSL 3.10 cannot declare storage image 'Target' of format rgba16"),
                  std::string::npos)
            << error.what();
    }
}

TEST(OpenGlForms, EveryResourceKindCompilesBack) {
    testing::TempFolder folder;
    CompileOptions options;
    options.source = folder.write("kinds.hlsl", R"(
cbuffer Params : register(b0) { float scale; };
Texture2D<float4> Unused;
Texture2D<float4> Input : register(t1);
Texture2D<float4> LoadedOnly;
SamplerState Linear;
RWTexture2D<float4> Output;
StructuredBuffer<float> Weights;
RWStructuredBuffer<float> Totals;
float gain;
[numthreads(1, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float4 v = Input.SampleLevel(Linear, float2(0.5, 0.5), 0) + LoadedOnly.Load(int3(0, 0, 0));
    Output[id.xy] = v * scale * Weights[0] * gain;
    Totals[0] = v.x;
}
)");
    const auto shader = compileShader(options);
    EXPECT_EQ(shader.reflection.find("Unused"), nullptr) << "an unused resource takes no register";
    EXPECT_EQ(shader.reflection.find("LoadedOnly")->location.registerName(), "t0");
    EXPECT_EQ(shader.reflection.find("$Global")->location.registerName(), "b1");
    for (auto target : {CrossTarget::Glsl, CrossTarget::Essl}) {
        const auto compiled = crossCompileShader(shader, target);
        EXPECT_NO_THROW(compileOpenGlGlsl(compiled.source, ShaderStage::Compute, "form")) << crossTargetName(target) << ":\n" << compiled.source;
        EXPECT_EQ(findBinding(compiled, "LoadedOnly")->declaredName, "LoadedOnly");
        EXPECT_EQ(findBinding(compiled, "Input+Linear")->slot, 1u) << "combined samplers follow their texture's register";
        EXPECT_EQ(findBinding(compiled, "Weights")->slot, 0u);
        EXPECT_EQ(findBinding(compiled, "Totals")->slot, 1u);
    }
}

TEST(MetalForm, EveryResourceGetsTheRecordedIndexInTheKernelSignature) {
    const auto msl = crossCompileShader(testing::compileSeed("PrefilterSpecularCS"), CrossTarget::Msl);
    EXPECT_NE(msl.source.find("kernel void main0("), std::string::npos);
    EXPECT_NE(msl.source.find("texturecube<float> EnvMap [[texture(0)]]"), std::string::npos) << msl.source;
    EXPECT_NE(msl.source.find("texture2d_array<float, access::write> Prefiltered [[texture(1)]]"), std::string::npos);
    EXPECT_NE(msl.source.find("sampler EnvMapSampler [[sampler(0)]]"), std::string::npos);
    EXPECT_NE(msl.source.find("[[buffer(0)]]"), std::string::npos);
    EXPECT_EQ(findBinding(msl, "Prefiltered")->slot, 1u);
    EXPECT_EQ(findBinding(msl, "Prefiltered")->namespace_, "texture");
}

TEST(HlslForm, KeepsTheOriginalRegisters) {
    const auto hlsl = crossCompileShader(testing::compileSeed("PrefilterSpecularCS"), CrossTarget::Hlsl);
    EXPECT_NE(hlsl.source.find("cbuffer PrefilterSpecularParameter : register(b0)"), std::string::npos) << hlsl.source;
    EXPECT_NE(hlsl.source.find("TextureCube<float4> EnvMap : register(t0);"), std::string::npos);
    EXPECT_NE(hlsl.source.find("SamplerState EnvMapSampler : register(s0);"), std::string::npos);
    EXPECT_NE(hlsl.source.find("RWTexture2DArray<float4> Prefiltered : register(u0);"), std::string::npos);
}

// SPIRV-Cross loads a float matrix from a byte-address buffer as asfloat(uint4x4(...)), which no
// SPIR-V compiler of HLSL types; the form must compile back and load the same components.
TEST(HlslForm, AMatrixInABufferIsLoadedAsFloats) {
    testing::TempFolder folder;
    CompileOptions options;
    options.source = folder.write("matrix.hlsl", R"(
struct Instance { float4x4 world; row_major float3x4 normal; };
StructuredBuffer<Instance> Instances;
RWStructuredBuffer<float4> Out;
[numthreads(1, 1, 1)]
void main() { Out[0] = mul(Instances[0].world, float4(1, 2, 3, 1)) + float4(mul(Instances[0].normal, float4(1, 1, 1, 0)), 0); }
)");
    const auto hlsl = crossCompileShader(compileShader(options), CrossTarget::Hlsl).source;
    EXPECT_EQ(hlsl.find("uint4x4"), std::string::npos) << hlsl;
    EXPECT_EQ(hlsl.find("uint3x4"), std::string::npos) << hlsl;
    EXPECT_NE(hlsl.find("float4x4(asfloat(Instances.Load(0)), asfloat(Instances.Load(16)),"), std::string::npos) << hlsl;
    options.sourceText = hlsl;
    EXPECT_NO_THROW(compileShader(options)) << hlsl;
}

TEST(HlslForm, OnlyAnIntegerMatrixCastIsRewritten) {
    EXPECT_EQ(withFloatMatrixLoads("m = asfloat(uint2x2(B.Load(0), f(1, 2), 3u, B.Load(12)));"),
              "m = float2x2(asfloat(B.Load(0)), asfloat(f(1, 2)), asfloat(3u), asfloat(B.Load(12)));");
    EXPECT_EQ(withFloatMatrixLoads("v = asfloat(uint4(a, b, c, d)); w = asfloat(uint2x2(a, b, c, d)).x;"),
              "v = asfloat(uint4(a, b, c, d)); w = float2x2(asfloat(a), asfloat(b), asfloat(c), asfloat(d)).x;");
    EXPECT_EQ(withFloatMatrixLoads("x = asfloat(uint2x2(a, b, c, d) + k);"), "x = asfloat(uint2x2(a, b, c, d) + k);");
}

// SPIR-V for OpenGL (ARB_gl_spirv) needs a location on every default-block uniform.
TEST(OpenGlForms, APushConstantBlockBecomesAUniformWithALocation) {
    testing::TempFolder folder;
    CompileOptions options;
    options.source = folder.write("push.hlsl", R"(
struct Parameters { float scale; uint offset; };
[[vk::push_constant]] Parameters Push;
RWStructuredBuffer<float> Out;
[numthreads(1, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) { Out[id.x] = id.x * Push.scale + Push.offset; }
)");
    const auto shader = compileShader(options);
    for (auto target : {CrossTarget::Glsl, CrossTarget::Essl}) {
        const auto compiled = crossCompileShader(shader, target);
        EXPECT_NE(compiled.source.find("layout(location = 0) uniform Push Push_1;"), std::string::npos) << compiled.source;
        ASSERT_NE(findBinding(compiled, "Push"), nullptr);
        EXPECT_EQ(findBinding(compiled, "Push")->namespace_, "uniform_location");
        EXPECT_NO_THROW(compileOpenGlGlsl(compiled.source, ShaderStage::Compute, "form")) << compiled.source;
    }
}

} // namespace
} // namespace iblkit::compiler
