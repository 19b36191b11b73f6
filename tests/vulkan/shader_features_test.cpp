// The optional shader features: enabled on the device where it has them (lavapipe has all of
// them, which the porting corpus's double, 64-bit and 16-bit runs need), and a module that needs
// one the device lacks named before a pipeline is made.
#include "shader_features.hpp"
#include "vulkan_test_support.hpp"

#include <gtest/gtest.h>

namespace iblkit::vulkan {
namespace {

const char* kDoubleShader = R"(
RWStructuredBuffer<float> Out : register(u0);
[numthreads(1, 1, 1)] void main() { double third = 1.0 / 3.0; Out[0] = (float)(third * 3.0); }
)";

TEST(ShaderFeatures, ACapabilityWithoutItsFeatureIsNamed) {
    const auto shader = testing::compileTestShader("Doubles", kDoubleShader);
    ShaderFeatures none;
    EXPECT_EQ(missingShaderFeature(shader.spirv, none), "Float64 (shaderFloat64)");
    ShaderFeatures doubles;
    doubles.float64 = true;
    EXPECT_EQ(missingShaderFeature(shader.spirv, doubles), "");
}

// shaderFeatures() is what the context enabled at device creation: every feature the device has.
// Lavapipe (the project's default device, installed with it) has every one of them.
TEST(EnabledShaderFeatures, OnLavapipeTheContextEnablesEveryOptionalShaderFeature) {
    auto log = std::make_shared<ValidationLog>();
    {
        ContextOptions options;
        options.device = "llvmpipe";
        options.validation = true;
        options.validationLog = log;
        const VulkanContext context(options);
        const auto& features = context.shaderFeatures();
        EXPECT_TRUE(features.float64 && features.int64 && features.int16 && features.float16 && features.int8);
        EXPECT_TRUE(features.storageBuffer16 && features.uniformBuffer16 && features.pushConstant16);
        const auto shader = testing::compileTestShader("Doubles", kDoubleShader);
        EXPECT_EQ(missingShaderFeature(shader.spirv, features), "");
    }
    for (const auto& message : log->messages()) ADD_FAILURE() << "validation: " << message;
}

} // namespace
} // namespace iblkit::vulkan
