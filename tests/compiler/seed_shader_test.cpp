// The document's two compute shaders: they compile, validate, and reflect exactly the
// resources, registers and bindings the register rule promises (docs/bindings.md).
#include "seed_test_support.hpp"

#include "compile_error.hpp"
#include "spirv_tools.hpp"

#include <gtest/gtest.h>

namespace iblkit::compiler {
namespace {

using testing::compileSeed;

struct ExpectedResource {
    std::string name;
    ResourceKind kind;
    std::string registerName;
    bool explicitRegister;
    uint32_t binding;
};

void expectResources(const ShaderReflection& reflection, const std::vector<ExpectedResource>& expected) {
    ASSERT_EQ(reflection.resources.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        const auto& actual = reflection.resources[i];
        SCOPED_TRACE(expected[i].name);
        EXPECT_EQ(actual.name, expected[i].name);
        EXPECT_EQ(actual.kind, expected[i].kind);
        EXPECT_EQ(actual.location.registerName(), expected[i].registerName);
        EXPECT_EQ(actual.location.explicitRegister, expected[i].explicitRegister);
        EXPECT_EQ(actual.location.set, 0u);
        EXPECT_EQ(actual.location.space, 0u);
        EXPECT_EQ(actual.location.binding, expected[i].binding);
    }
}

TEST(SeedShaders, EveryManifestShaderCompilesToValidSpirvInEveryOptimization) {
    for (const auto& entry : compiler::readShaderManifest(testing::kManifest)) {
        for (auto level : {OptimizationLevel::None, OptimizationLevel::Performance, OptimizationLevel::Size}) {
            SCOPED_TRACE(entry.name);
            auto options = entry.options;
            options.optimization = level;
            const auto shader = compileShader(options);
            ASSERT_GT(shader.spirv.size(), 5u);
            EXPECT_EQ(shader.spirv[0], 0x07230203u) << "SPIR-V magic number";
            EXPECT_NO_THROW(validateSpirv(shader.spirv, entry.name));
            EXPECT_TRUE(shader.warnings.empty()) << shader.warnings.front();
        }
    }
}

TEST(SeedShaders, PrefilterReflectsItsFourResourcesWithoutABindingClash) {
    const auto shader = compileSeed("PrefilterSpecularCS");
    const auto& reflection = shader.reflection;
    EXPECT_EQ(reflection.stage, ShaderStage::Compute);
    EXPECT_EQ(reflection.workgroupSize, (std::array<uint32_t, 3>{8, 8, 1}));
    // b0 is written in the source; t0, s0 and u0 are the first free registers of their classes.
    expectResources(reflection, {{"PrefilterSpecularParameter", ResourceKind::ConstantBuffer, "b0", true, 0},
                                 {"EnvMap", ResourceKind::Texture, "t0", false, 32},
                                 {"EnvMapSampler", ResourceKind::Sampler, "s0", false, 64},
                                 {"Prefiltered", ResourceKind::StorageImage, "u0", false, 96}});
    const auto* parameters = reflection.find("PrefilterSpecularParameter");
    ASSERT_EQ(parameters->members.size(), 1u);
    EXPECT_EQ(parameters->members[0].name, "Roughness");
    EXPECT_EQ(parameters->members[0].type, "float");
    EXPECT_EQ(parameters->members[0].offset, 0u);
    EXPECT_EQ(parameters->members[0].size, 4u);
    EXPECT_EQ(reflection.find("EnvMap")->dimension, "cube");
    EXPECT_EQ(reflection.find("Prefiltered")->dimension, "2d_array");
    EXPECT_EQ(reflection.find("Prefiltered")->format, "rgba32f");
}

TEST(SeedShaders, LutReflectsOneStorageImageInTheDocumentsFormat) {
    const auto shader = compileSeed("PrecomputedBrdfCS");
    expectResources(shader.reflection, {{"Precomputed", ResourceKind::StorageImage, "u0", false, 96}});
    const auto* lut = shader.reflection.find("Precomputed");
    EXPECT_EQ(lut->dimension, "2d");
    EXPECT_EQ(lut->format, "rg16f");
    EXPECT_EQ(lut->vulkanFormat, "R16G16_SFLOAT");
}

TEST(SeedShaders, TheSameInputGivesByteIdenticalOutputs) {
    const auto first = compileSeed("PrefilterSpecularCS");
    const auto second = compileSeed("PrefilterSpecularCS");
    EXPECT_EQ(first.spirv, second.spirv);
    for (auto target : {CrossTarget::Glsl, CrossTarget::Essl, CrossTarget::Msl, CrossTarget::Hlsl})
        EXPECT_EQ(crossCompileShader(first, target).source, crossCompileShader(second, target).source)
            << crossTargetName(target);
    EXPECT_EQ(reflectionJson(first, {}), reflectionJson(second, {}));
}

TEST(SeedShaders, DepfileListsTheSourceAndEveryInclude) {
    const auto shader = compileSeed("PrecomputedBrdfCS");
    EXPECT_EQ(makeDepfile("out/lut.spv", shader), "out/lut.spv: hlsl/document/PrecomputedBrdfCS.hlsl \\\n  hlsl/document/Common/PBR.fxh\n");
}

TEST(SeedShaders, StripRemovesNamesButKeepsTheReflection) {
    auto options = testing::manifestShader("PrefilterSpecularCS").options;
    options.stripDebugInfo = true;
    const auto stripped = compileShader(options);
    EXPECT_EQ(disassembleSpirv(stripped.spirv).find("OpName"), std::string::npos);
    EXPECT_NE(disassembleSpirv(stripped.namedSpirv).find("OpName %EnvMap"), std::string::npos);
    EXPECT_EQ(stripped.reflection.resources.size(), 4u);
}

TEST(SeedShaders, SampleCountDefineReachesTheLoops) {
    auto options = testing::manifestShader("PrecomputedBrdfCS").options;
    options.defines["SAMPLE_COUNT"] = "64";
    const auto text = disassembleSpirv(compileShader(options).spirv);
    EXPECT_NE(text.find("%uint_64"), std::string::npos);
    EXPECT_EQ(text.find("%uint_1024"), std::string::npos);
}

TEST(ShaderManifest, AMethodIsANameOrAListOfThem) {
    const auto parse = [](const std::string& method) {
        return parseShaderManifest(R"({"shaders": [{"name": "A", "source": "a.hlsl", "method": )" + method + "}]}",
                                   "hlsl/shaders.json");
    };
    EXPECT_EQ(parse(R"("pyramid")").at(0).methods, std::vector<std::string>{"pyramid"});
    EXPECT_EQ(parse(R"(["pyramid", "mipchain"])").at(0).methods, (std::vector<std::string>{"pyramid", "mipchain"}));
    EXPECT_THROW(parse("[]"), CompileError);
    EXPECT_THROW(parse("3"), CompileError);
}

} // namespace
} // namespace iblkit::compiler
