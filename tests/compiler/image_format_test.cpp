// Storage image formats stated by resource name reach the SPIR-V, and impossible ones are refused.
#include "compile_error.hpp"
#include "compiler.hpp"
#include "seed_test_support.hpp"
#include "spirv_tools.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

namespace iblkit::compiler {
namespace {

std::string imageTypeOf(const CompiledShader& shader) {
    const auto text = disassembleSpirv(shader.spirv);
    const auto at = text.find("OpTypeImage");
    return at == std::string::npos ? "" : text.substr(at, text.find('\n', at) - at);
}

TEST(ImageFormat, WithoutAnOverrideGlslangInfersRg32fFromFloat2) {
    auto options = testing::manifestShader("PrecomputedBrdfCS").options;
    options.imageFormats.clear();
    EXPECT_EQ(imageTypeOf(compileShader(options)), "OpTypeImage %float 2D 0 0 0 2 Rg32f");
}

TEST(ImageFormat, TheManifestGivesTheLutTheDocumentsR16G16Float) {
    const auto shader = testing::compileSeed("PrecomputedBrdfCS");
    EXPECT_EQ(imageTypeOf(shader), "OpTypeImage %float 2D 0 0 0 2 Rg16f");
    EXPECT_NE(disassembleSpirv(shader.spirv).find("OpCapability StorageImageExtendedFormats"), std::string::npos);
}

TEST(ImageFormat, OverrideSurvivesOptimization) {
    auto options = testing::manifestShader("PrecomputedBrdfCS").options;
    options.optimization = OptimizationLevel::Performance;
    EXPECT_EQ(imageTypeOf(compileShader(options)), "OpTypeImage %float 2D 0 0 0 2 Rg16f");
}

TEST(ImageFormat, AnImageSharingItsTypeWithAnotherGetsATypeOfItsOwn) {
    testing::TempFolder folder;
    CompileOptions options;
    options.source = folder.write("two.hlsl", R"(
RWTexture2D<float4> Half;
RWTexture2D<float4> Full;
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { Half[id.xy] = float4(1, 2, 3, 4); Full[id.xy] = float4(5, 6, 7, 8); }
)");
    options.imageFormats["Half"] = "rgba16";
    const auto shader = compileShader(options); // validated inside
    EXPECT_EQ(shader.reflection.find("Half")->format, "rgba16");
    EXPECT_EQ(shader.reflection.find("Full")->format, "rgba32f");
    EXPECT_NE(disassembleSpirv(shader.spirv).find("OpCapability StorageImageExtendedFormats"), std::string::npos)
        << "rgba16 (UNORM) is an extended format";
}

void expectRefused(std::map<std::string, std::string> formats, const std::string& expectedText) {
    auto options = testing::manifestShader("PrecomputedBrdfCS").options;
    options.imageFormats = std::move(formats);
    try {
        compileShader(options);
        ADD_FAILURE() << "expected CompileError containing: " << expectedText;
    } catch (const CompileError& error) {
        EXPECT_NE(std::string(error.what()).find(expectedText), std::string::npos) << error.what();
    }
}

// A format wider than the element (an R16G16B16A16 view of a float2 UAV) is legal: the writes
// are widened to four components, which spirv-val and Vulkan's rule 07112 then accept.
TEST(ImageFormat, MoreChannelsThanTheElementTypeWidensTheWrites) {
    auto options = testing::manifestShader("PrecomputedBrdfCS").options;
    options.imageFormats = {{"Precomputed", "rgba16f"}};
    const auto text = disassembleSpirv(compileShader(options).spirv); // validated inside
    EXPECT_NE(text.find("OpTypeImage %float 2D 0 0 0 2 Rgba16f"), std::string::npos);
    const auto write = text.find("OpImageWrite");
    ASSERT_NE(write, std::string::npos);
    const std::string line = text.substr(write, text.find('\n', write) - write); // OpImageWrite %image %coordinate %texel
    const std::string texel = line.substr(line.rfind(' ') + 1);
    EXPECT_NE(text.find(texel + " = OpCompositeConstruct %v4float"), std::string::npos) << line;
}

TEST(ImageFormat, AnotherComponentTypeIsRefused) {
    expectRefused({{"Precomputed", "rg16ui"}}, "does not match the component type");
}

TEST(ImageFormat, AnUnknownFormatIsRefusedWithTheKnownOnes) {
    expectRefused({{"Precomputed", "rg17f"}}, "unknown image format 'rg17f' (known: rgba32f");
}

TEST(ImageFormat, AnUnknownResourceIsRefused) {
    expectRefused({{"Precomputd", "rg16f"}}, "names 'Precomputd', which the entry point does not use");
}

} // namespace
} // namespace iblkit::compiler
