// Cube faces: layer i of a cube is Vulkan's face i (+X, -X, +Y, -Y, +Z, -Z), sampling follows
// the Vulkan specification's face-selection table, and the prefilter shader's own face ->
// direction table (Direct3D 9's cubic environment mapping) agrees with it.
#include "compute_program.hpp"
#include "vulkan_test_support.hpp"

#include "cube_environment.hpp"
#include "pbr.hpp"
#include "shader_manifest.hpp"


namespace iblkit::vulkan {
namespace {

constexpr uint32_t kSize = 8;

// Every texel holds (face, column, row, 1): a lookup tells exactly which texel it hit.
Image identityCube(const VulkanContext& context) {
    Image cube(context, {"EnvMap", &texelFormatNamed("R32G32B32A32_SFLOAT"), kSize, kSize, 6, 1, true, false});
    std::vector<float> values;
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t y = 0; y < kSize; ++y)
            for (uint32_t x = 0; x < kSize; ++x) values.insert(values.end(), {float(face), float(x), float(y), 1.0f});
    cube.upload(context, values);
    return cube;
}

void expectEveryTexelFoundItself(const std::vector<float>& values) {
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t y = 0; y < kSize; ++y)
            for (uint32_t x = 0; x < kSize; ++x) {
                const size_t at = ((face * kSize + y) * kSize + x) * 4;
                ASSERT_EQ(values[at], float(face)) << "face " << face << " (" << x << ", " << y << ")";
                ASSERT_EQ(values[at + 1], float(x)) << "face " << face << " (" << x << ", " << y << ")";
                ASSERT_EQ(values[at + 2], float(y)) << "face " << face << " (" << x << ", " << y << ")";
            }
}

// The reference's transcription of the shader's table against the Vulkan specification's
// face-selection table, texel by texel.
TEST(CubeConvention, TheSeedShadersFaceTableIsVulkans) {
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t y = 0; y < kSize; ++y)
            for (uint32_t x = 0; x < kSize; ++x) {
                const glm::dvec3 seed = reference::PrefilterFaceDirection<double>(face, x, y, kSize);
                const glm::dvec3 vulkan = glm::normalize(reference::cubeTexelDirection(face, x, y, kSize));
                EXPECT_LT(glm::length(seed - vulkan), 1e-15) << "face " << face << " (" << x << ", " << y << ")";
            }
}

class CubeOrientation : public testing::VulkanTest {};

TEST_F(CubeOrientation, SamplingAlongVulkansDirectionOfATexelReturnsThatTexel) {
    const auto shader = testing::compileTestShader("cube_lookup", R"(
TextureCube<float4> EnvMap;
SamplerState Nearest;
RWTexture2DArray<float4> Found;
float3 vulkanDirection(uint face, float2 st) {
    float a = 2 * st.x - 1, b = 2 * st.y - 1;
    if (face == 0) return float3(1, -b, -a);
    if (face == 1) return float3(-1, -b, a);
    if (face == 2) return float3(a, 1, b);
    if (face == 3) return float3(a, -1, -b);
    if (face == 4) return float3(a, -b, 1);
    return float3(-a, -b, -1);
}
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float2 st = (id.xy + 0.5) / 8.0;
    Found[id] = EnvMap.SampleLevel(Nearest, vulkanDirection(id.z, st), 0);
}
)");
    auto env = identityCube(context());
    Image found(context(), {"Found", &texelFormatNamed("R32G32B32A32_SFLOAT"), kSize, kSize, 6, 1, false, true});
    const Sampler nearest(context(), {vk::Filter::eNearest, vk::SamplerMipmapMode::eNearest, vk::SamplerAddressMode::eClampToEdge});
    ComputeProgram program(context(), shader.spirv, shader.reflection);
    program.bind("EnvMap", env);
    program.bind("Nearest", nearest);
    program.bind("Found", found);
    program.dispatchThreads(context(), {kSize, kSize, 6});
    expectEveryTexelFoundItself(found.download(context()));
}

// At roughness 0 every GGX sample is the normal, so the prefilter shader returns the
// environment along its own direction for the texel: with the identity cube each output texel
// must name itself. A swapped or mirrored face in the shader's table fails here.
TEST_F(CubeOrientation, ThePrefilterShaderAtRoughnessZeroFindsEachTexelItself) {
    auto options = compiler::manifestShaderOptions("hlsl/shaders.json", "PrefilterSpecularCS");
    options.defines["SAMPLE_COUNT"] = "4";
    const auto shader = compiler::compileShader(options);
    auto env = identityCube(context());
    Image prefiltered(context(), {"Prefiltered", &texelFormatNamed("R32G32B32A32_SFLOAT"), kSize, kSize, 6, 1, false, true});
    const Sampler nearest(context(), {vk::Filter::eNearest, vk::SamplerMipmapMode::eNearest, vk::SamplerAddressMode::eClampToEdge});
    Buffer parameters(context(), 16, vk::BufferUsageFlagBits::eUniformBuffer, "PrefilterSpecularParameter");
    const float roughness[4] = {0, 0, 0, 0};
    parameters.write(std::as_bytes(std::span(roughness)));
    ComputeProgram program(context(), shader.spirv, shader.reflection);
    program.bind("EnvMap", env);
    program.bind("EnvMapSampler", nearest);
    program.bind("Prefiltered", prefiltered);
    program.bind("PrefilterSpecularParameter", parameters);
    program.dispatchThreads(context(), {kSize, kSize, 6});
    expectEveryTexelFoundItself(prefiltered.download(context()));
}

} // namespace
} // namespace iblkit::vulkan
