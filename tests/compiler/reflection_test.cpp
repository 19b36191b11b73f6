// Reflection of what the seed shaders lack: specialization and push constants, cbuffer packing.
#include "compile_error.hpp"
#include "compiler.hpp"
#include "temp_folder.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace iblkit::compiler {
namespace {

ShaderReflection reflect(const std::string& source) {
    testing::TempFolder folder;
    CompileOptions options;
    options.source = folder.write("shader.hlsl", source);
    return compileShader(options).reflection;
}

TEST(Reflection, SpecializationConstantsWithTheirIdsTypesAndDefaults) {
    const auto reflection = reflect(R"(
[[vk::constant_id(3)]] const uint SampleCount = 256;
[[vk::constant_id(4)]] const float Bias = 0.25;
RWTexture2D<float4> Output;
[numthreads(4, 2, 1)]
void main(uint3 id : SV_DispatchThreadID) { Output[id.xy] = SampleCount * Bias; }
)");
    ASSERT_EQ(reflection.specializationConstants.size(), 2u);
    EXPECT_EQ(reflection.specializationConstants[0].name, "SampleCount");
    EXPECT_EQ(reflection.specializationConstants[0].constantId, 3u);
    EXPECT_EQ(reflection.specializationConstants[0].type, "uint");
    EXPECT_EQ(reflection.specializationConstants[0].defaultValue, 256.0);
    EXPECT_EQ(reflection.specializationConstants[1].type, "float");
    EXPECT_EQ(reflection.specializationConstants[1].defaultValue, 0.25);
    EXPECT_EQ(reflection.workgroupSize, (std::array<uint32_t, 3>{4, 2, 1}));
}

TEST(Reflection, PushConstantBlockTakesNoRegister) {
    for (const char* declaration : {"struct Push { float4 tint; uint face; };\n[[vk::push_constant]] ConstantBuffer<Push> PushBlock;",
                                    "[[vk::push_constant]] cbuffer PushBlock { float4 tint; uint face; };"}) {
        SCOPED_TRACE(declaration);
        const bool member = std::string(declaration).find("ConstantBuffer") != std::string::npos;
        const auto reflection = reflect(std::string(declaration) + R"(
RWTexture2D<float4> Output;
[numthreads(1, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) { Output[id.xy] = )" + (member ? "PushBlock.tint + PushBlock.face" : "tint + face") + "; }\n");
        EXPECT_EQ(reflection.pushConstantBlock, "PushBlock");
        EXPECT_EQ(reflection.pushConstantSize, 20u);
        ASSERT_EQ(reflection.pushConstants.size(), 2u);
        EXPECT_EQ(reflection.pushConstants[1].name, "face");
        EXPECT_EQ(reflection.pushConstants[1].offset, 16u);
        ASSERT_EQ(reflection.resources.size(), 1u);
        EXPECT_EQ(reflection.resources[0].location.registerName(), "u0");
    }
}

TEST(Reflection, CbufferMembersFollowDirect3DPacking) {
    // Direct3D packs a float2 right after a float (offset 4); std140 would put it at 8.
    const auto reflection = reflect(R"(
cbuffer Params : register(b2) { float a; float2 b; float3 c; float d; float4x4 m; };
RWTexture2D<float4> Output;
[numthreads(1, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) { Output[id.xy] = a + b.x + c.x + d + m[0][0]; }
)");
    const auto* params = reflection.find("Params");
    ASSERT_NE(params, nullptr);
    ASSERT_EQ(params->members.size(), 5u);
    const std::vector<std::pair<std::string, uint32_t>> expected = {{"a", 0}, {"b", 4}, {"c", 16}, {"d", 28}, {"m", 32}};
    for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(params->members[i].name, expected[i].first);
        EXPECT_EQ(params->members[i].offset, expected[i].second) << expected[i].first;
    }
    EXPECT_EQ(params->members[4].type, "float4x4");
    EXPECT_EQ(params->members[4].size, 64u);
}

TEST(Reflection, JsonCarriesEveryField) {
    const auto reflection = reflect(R"(
Texture2DArray<float4> Layers : register(t3, space1);
SamplerState Point : register(s2);
RWTexture2D<float2> Lut;
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { Lut[id.xy] = Layers.SampleLevel(Point, float3(0, 0, 1), 0).xy; }
)");
    const auto json = toJson(reflection);
    const auto& layers = json.at("resources").at(0);
    EXPECT_EQ(layers.at("name"), "Layers");
    EXPECT_EQ(layers.at("kind"), "texture");
    EXPECT_EQ(layers.at("register"), "t3");
    EXPECT_EQ(layers.at("space"), 1);
    EXPECT_EQ(layers.at("set"), 1);
    EXPECT_EQ(layers.at("binding"), 35);
    EXPECT_EQ(layers.at("dimension"), "2d_array");
    EXPECT_EQ(layers.at("component_type"), "float");
    const auto& lut = json.at("resources").at(2);
    EXPECT_EQ(lut.at("format"), "rg32f");
    EXPECT_EQ(lut.at("vulkan_format"), "R32G32_SFLOAT");
    EXPECT_EQ(json.at("workgroup_size"), nlohmann::json::array({8, 8, 1}));
}

void expectSameMembers(const std::vector<BlockMember>& read, const std::vector<BlockMember>& written) {
    ASSERT_EQ(read.size(), written.size());
    for (size_t i = 0; i < read.size(); ++i) {
        EXPECT_EQ(read[i].name, written[i].name);
        EXPECT_EQ(read[i].type, written[i].type);
        EXPECT_EQ(read[i].offset, written[i].offset);
        EXPECT_EQ(read[i].size, written[i].size);
    }
}

void expectSameResource(const ReflectedResource& read, const ReflectedResource& written) {
    SCOPED_TRACE(written.name);
    EXPECT_EQ(read.name, written.name);
    EXPECT_EQ(read.kind, written.kind);
    EXPECT_EQ(read.dimension, written.dimension);
    EXPECT_EQ(read.format, written.format);
    EXPECT_EQ(read.vulkanFormat, written.vulkanFormat);
    EXPECT_EQ(read.componentType, written.componentType);
    EXPECT_EQ(read.readOnly, written.readOnly);
    EXPECT_EQ(read.blockSize, written.blockSize);
    expectSameMembers(read.members, written.members);
    const auto &a = read.location, &b = written.location;
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.registerClass, b.registerClass);
    EXPECT_EQ(a.vulkanBinding, b.vulkanBinding);
    if (!b.vulkanBinding) {
        EXPECT_EQ(a.registerIndex, b.registerIndex);
        EXPECT_EQ(a.space, b.space);
    }
    EXPECT_EQ(a.count, b.count);
    EXPECT_EQ(a.explicitRegister, b.explicitRegister);
    EXPECT_EQ(a.set, b.set);
    EXPECT_EQ(a.binding, b.binding);
}

// Compiled kernels are cached with their reflection as JSON: what is read back must bind as the
// compile's own does, field by field, for every kind of resource.
TEST(Reflection, JsonReadsBackEveryField) {
    const auto written = reflect(R"(
[[vk::constant_id(3)]] const uint SampleCount = 256;
struct Push { float Scale; uint Count; };
[[vk::push_constant]] Push push;
cbuffer Parameters : register(b2, space1) { float4x4 Transform; float Roughness; uint2 Size; };
Texture2D<float4> Source : register(t3);
TextureCube<float4> Environment;
SamplerState Linear : register(s1);
StructuredBuffer<float2> Nodes;
RWStructuredBuffer<uint> Counts : register(u5);
RWTexture2D<float2> Output;
Buffer<float> Weights;
[[vk::binding(7, 2)]] RWTexture2DArray<float4> Faces;
[numthreads(8, 4, 2)]
void main(uint3 id : SV_DispatchThreadID) {
    float4 c = Source.SampleLevel(Linear, float2(id.xy) / Size, 0) + Environment.SampleLevel(Linear, float3(1, 0, 0), 0);
    Output[id.xy] = c.xy * Transform[0].x * Roughness * Nodes[id.x] * push.Scale * Weights[id.x] * SampleCount;
    Faces[id] = c;
    InterlockedAdd(Counts[0], push.Count);
}
)");
    const auto read = reflectionFromJson(toJson(written));
    EXPECT_EQ(read.entryPoint, written.entryPoint);
    EXPECT_EQ(read.stage, written.stage);
    EXPECT_EQ(read.workgroupSize, written.workgroupSize);
    ASSERT_EQ(read.resources.size(), written.resources.size());
    for (size_t i = 0; i < read.resources.size(); ++i) expectSameResource(read.resources[i], written.resources[i]);
    EXPECT_EQ(read.pushConstantBlock, written.pushConstantBlock);
    EXPECT_EQ(read.pushConstantSize, written.pushConstantSize);
    expectSameMembers(read.pushConstants, written.pushConstants);
    ASSERT_EQ(read.specializationConstants.size(), 1u);
    EXPECT_EQ(read.specializationConstants[0].constantId, 3u);
    EXPECT_EQ(read.specializationConstants[0].defaultValue, 256);
    EXPECT_EQ(toJson(read), toJson(written));
}

TEST(Reflection, MalformedJsonIsACompileError) {
    auto json = toJson(reflect("RWTexture2D<float> Output;\n[numthreads(1, 1, 1)] void main() { Output[uint2(0, 0)] = 1; }\n"));
    json["resources"][0]["register"] = "x9";
    EXPECT_THROW(reflectionFromJson(json), CompileError);
    json.erase("resources");
    EXPECT_THROW(reflectionFromJson(json), CompileError);
    EXPECT_THROW(reflectionFromJson(nlohmann::json::array()), CompileError);
}

} // namespace
} // namespace iblkit::compiler
