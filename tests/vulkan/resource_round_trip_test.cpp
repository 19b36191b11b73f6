// Every supported format, mip and layer survives an upload and a readback, and a shader
// writes every storage format the kit uses at every mip.
#include "block_writer.hpp"
#include "compute_program.hpp"
#include "half_float.hpp"
#include "vulkan_error.hpp"
#include "vulkan_test_support.hpp"

#include <cmath>
#include <cstring>

namespace iblkit::vulkan {
namespace {

// A value per (mip, layer, row, column, channel), exactly representable in the format.
float patternValue(const TexelFormat& format, size_t index) {
    if (format.kind == ComponentKind::UNorm) return float(index % 256) / 255.0f;
    if (format.bytesPerChannel == 2) return float(index % 2048) / 64.0f; // halves hold these exactly
    return float(index) * 0.37f + 1e-3f;
}

struct Shape {
    const char* name;
    uint32_t width, height, layers, mips;
    bool cube;
};

class RoundTrip : public testing::VulkanTest, public ::testing::WithParamInterface<std::tuple<const char*, Shape>> {};

TEST_P(RoundTrip, UploadThenReadbackGivesTheSameValues) {
    const auto& [formatName, shape] = GetParam();
    const auto& format = texelFormatNamed(formatName);
    Image image(context(), {"pattern", &format, shape.width, shape.height, shape.layers, shape.mips, shape.cube, false});
    std::vector<float> values(image.valueCount());
    for (size_t i = 0; i < values.size(); ++i) values[i] = patternValue(format, i);
    image.upload(context(), values);
    const auto back = image.download(context());
    ASSERT_EQ(back.size(), values.size());
    for (size_t i = 0; i < values.size(); ++i) ASSERT_EQ(back[i], values[i]) << "value " << i;
}

INSTANTIATE_TEST_SUITE_P(
    FormatsAndShapes, RoundTrip,
    ::testing::Combine(::testing::Values("R16G16_SFLOAT", "R32G32_SFLOAT", "R16G16B16A16_SFLOAT", "R32G32B32A32_SFLOAT",
                                         "R32_SFLOAT", "R16_SFLOAT", "R8G8B8A8_UNORM"),
                       ::testing::Values(Shape{"Plain13x7FullMips", 13, 7, 1, 4, false},
                                         Shape{"Array3Layers", 8, 8, 3, 4, false},
                                         Shape{"Cube16FullMips", 16, 16, 6, 5, true})),
    [](const auto& info) { return std::string(std::get<0>(info.param)) + "_" + std::get<1>(info.param).name; });

// Vulkan leaves the rounding of a shader's float written to a 16-bit float texel undefined:
// either representable neighbour is correct (lavapipe truncates, round-to-nearest-even is the
// other common choice). For positive values only, as the test writes.
bool isAHalfNeighbour(float value, float written) {
    const uint16_t nearestBits = numeric::toHalfBits(written);
    const float nearest = numeric::fromHalfBits(nearestBits);
    if (nearest == written) return value == written;
    const float other = numeric::fromHalfBits(nearest < written ? nearestBits + 1 : nearestBits - 1);
    return value == nearest || value == other;
}

class StorageWrite : public testing::VulkanTest, public ::testing::WithParamInterface<std::tuple<const char*, const char*, int>> {};

// The shader writes (x + 100 * layer + 1000 * mip, y) into the first two channels, and 1, 2 into the others.
TEST_P(StorageWrite, EveryMipAndLayerHoldsWhatTheShaderWrote) {
    const auto& [vulkanName, glslName, channels] = GetParam();
    const std::string type = channels == 2 ? "float2" : "float4";
    const std::string value = channels == 2 ? "float2(x, id.y)" : "float4(x, id.y, 1, 2)";
    const auto shader = testing::compileTestShader("write_" + std::string(glslName), R"(
cbuffer Level : register(b0) { uint mip; };
RWTexture2DArray<)" + type + R"(> Target;
[numthreads(4, 4, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint3 size; Target.GetDimensions(size.x, size.y, size.z);
    if (any(id >= size)) return;
    float x = id.x + 100.0 * id.z + 1000.0 * mip;
    Target[id] = )" + value + R"(;
}
)", {{"Target", glslName}});
    const auto& format = texelFormatNamed(vulkanName);
    Image image(context(), {"Target", &format, 16, 16, 6, 5, true, true});
    Buffer level(context(), 16, vk::BufferUsageFlagBits::eUniformBuffer, "Level");
    ComputeProgram program(context(), shader.spirv, shader.reflection);
    program.bind("Level", level);
    for (uint32_t mip = 0; mip < 5; ++mip) {
        const uint32_t mipValue[4] = {mip, 0, 0, 0};
        level.write(std::as_bytes(std::span(mipValue)));
        program.bind("Target", image, mip);
        program.dispatchThreads(context(), {image.mipWidth(mip), image.mipHeight(mip), 6});
    }
    const auto values = image.download(context());
    const bool half = format.bytesPerChannel == 2;
    for (uint32_t mip = 0; mip < 5; ++mip)
        for (uint32_t layer = 0; layer < 6; ++layer)
            for (uint32_t y = 0; y < image.mipHeight(mip); ++y)
                for (uint32_t x = 0; x < image.mipWidth(mip); ++x) {
                    const size_t at = image.valueOffset(mip, layer) + (size_t(y) * image.mipWidth(mip) + x) * channels;
                    const float written = x + 100.0f * layer + 1000.0f * mip; // at most 4515: inside a half's range
                    const bool right = half ? isAHalfNeighbour(values[at], written) : values[at] == written;
                    ASSERT_TRUE(right) << values[at] << " for " << written << " at mip " << mip << " layer " << layer
                                       << " (" << x << ", " << y << ")";
                    ASSERT_EQ(values[at + 1], float(y));
                    if (channels == 4) {
                        ASSERT_EQ(values[at + 2], 1.0f);
                        ASSERT_EQ(values[at + 3], 2.0f);
                    }
                }
}

INSTANTIATE_TEST_SUITE_P(KitFormats, StorageWrite,
                         ::testing::Values(std::tuple("R16G16_SFLOAT", "rg16f", 2), std::tuple("R32G32_SFLOAT", "rg32f", 2),
                                           std::tuple("R16G16B16A16_SFLOAT", "rgba16f", 4),
                                           std::tuple("R32G32B32A32_SFLOAT", "rgba32f", 4)),
                         [](const auto& info) { return std::string(std::get<0>(info.param)); });

class BufferRoundTrip : public testing::VulkanTest {};

TEST_F(BufferRoundTrip, AShaderReadsOneBufferAndWritesAnother) {
    const auto shader = testing::compileTestShader("buffers", R"(
cbuffer Scale : register(b0) { float factor; uint count; };
StructuredBuffer<float> Input;
RWStructuredBuffer<float> Output;
[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) { if (id.x < count) Output[id.x] = Input[id.x] * factor; }
)");
    std::vector<float> input(1000);
    for (size_t i = 0; i < input.size(); ++i) input[i] = float(i) - 0.5f;
    Buffer in(context(), input.size() * 4, vk::BufferUsageFlagBits::eStorageBuffer, "Input");
    Buffer out(context(), input.size() * 4, vk::BufferUsageFlagBits::eStorageBuffer, "Output");
    Buffer scale(context(), 16, vk::BufferUsageFlagBits::eUniformBuffer, "Scale");
    in.write(std::as_bytes(std::span(input)));
    ComputeProgram program(context(), shader.spirv, shader.reflection);
    const auto* block = shader.reflection.find("Scale");
    scale.write(packBlock("Scale", block->members, block->blockSize, {{"factor", {2.0}}, {"count", {1000}}}));
    program.bind("Input", in);
    program.bind("Output", out);
    program.bind("Scale", scale);
    program.dispatchThreads(context(), {1000, 1, 1});
    const auto bytes = out.read();
    std::vector<float> output(input.size());
    std::memcpy(output.data(), bytes.data(), bytes.size());
    for (size_t i = 0; i < input.size(); ++i) ASSERT_EQ(output[i], input[i] * 2.0f) << i;
}

} // namespace
} // namespace iblkit::vulkan

namespace iblkit::vulkan {
namespace {

class Constants : public testing::VulkanTest {};

TEST_F(Constants, SpecializationAndPushConstantsReachTheShaderByName) {
    const auto shader = testing::compileTestShader("constants", R"(
[[vk::constant_id(7)]] const uint Multiplier = 1;
[[vk::constant_id(9)]] const float Offset = 0.0;
[[vk::push_constant]] cbuffer Push { float scale; uint base; };
RWStructuredBuffer<float> Output;
[numthreads(4, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) { Output[id.x] = (base + id.x) * Multiplier * scale + Offset; }
)");
    Buffer output(context(), 4 * 4, vk::BufferUsageFlagBits::eStorageBuffer, "Output");
    ComputeProgram program(context(), shader.spirv, shader.reflection, {{"Multiplier", 3}, {"Offset", 0.5}});
    program.bind("Output", output);
    program.setPushConstants(packBlock("Push", shader.reflection.pushConstants, shader.reflection.pushConstantSize,
                                       {{"scale", {2.0}}, {"base", {10}}}));
    program.dispatchGroups(context(), {1, 1, 1});
    const auto bytes = output.read();
    float values[4];
    std::memcpy(values, bytes.data(), sizeof values);
    for (uint32_t i = 0; i < 4; ++i) EXPECT_EQ(values[i], (10.0f + i) * 3 * 2 + 0.5f) << i;
    EXPECT_THROW(ComputeProgram(context(), shader.spirv, shader.reflection, {{"Multiplyer", 3}}), VulkanError);
}

} // namespace
} // namespace iblkit::vulkan
