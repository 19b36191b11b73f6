// The document's shaders run on the default device, validation-clean.
#include "compute_program.hpp"
#include "vulkan_test_support.hpp"

#include "shader_manifest.hpp"

#include <cmath>

namespace iblkit::vulkan {
namespace {

compiler::CompiledShader seed(const std::string& name) {
    return compiler::compileShader(compiler::manifestShaderOptions("hlsl/shaders.json", name));
}

class SeedRun : public testing::VulkanTest {};

TEST_F(SeedRun, LutFillsA512SquareR16G16FloatImage) {
    const auto shader = seed("PrecomputedBrdfCS");
    ComputeProgram program(context(), shader.spirv, shader.reflection);
    Image lut(context(), {"Precomputed", &texelFormatNamed("R16G16_SFLOAT"), 512, 512, 1, 1, false, true});
    program.bind("Precomputed", lut);
    const auto timing = program.dispatchThreads(context(), {512, 512, 1});
    EXPECT_EQ(timing.groups, (std::array<uint32_t, 3>{64, 64, 1}));
    EXPECT_GT(timing.wallMilliseconds, 0.0);
    const auto values = lut.download(context());
    ASSERT_EQ(values.size(), 512u * 512u * 2u);
    // Plausibility only (the reference comparison is the consistency suite's): finite, in
    // [0, 1.01], and at NoV = 1, roughness -> 0 the scale is 1 and the bias 0.
    size_t finite = 0;
    for (float value : values) finite += std::isfinite(value) && value >= 0.0f && value <= 1.01f;
    EXPECT_EQ(finite, values.size());
    const size_t smoothHead = (0 * 512 + 511) * 2; // row roughness ~0, column NoV ~1
    EXPECT_NEAR(values[smoothHead], 1.0f, 0.01f);
    EXPECT_NEAR(values[smoothHead + 1], 0.0f, 0.01f);
}

} // namespace
} // namespace iblkit::vulkan
