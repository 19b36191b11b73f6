// HLSL as Direct3D code bases write it, through the whole compile: HLSL 2021 lowered for
// glslang, [[vk::...]] attributes honoured as written, errors pointing at the user's files.
#include "compile_error.hpp"
#include "compiler.hpp"
#include "spirv_tools.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

namespace iblkit::compiler {
namespace {

class Hlsl2021 : public ::testing::Test {
protected:
    CompiledShader compile(const std::string& text, lowering::HlslVersion version = lowering::HlslVersion::Hlsl2021) {
        CompileOptions options;
        options.source = folder.write("shader.hlsl", text);
        options.includeDirs.push_back(folder.path());
        options.hlslVersion = version;
        return compileShader(options);
    }
    std::string errorOf(const std::string& text, lowering::HlslVersion version = lowering::HlslVersion::Hlsl2021) {
        try {
            compile(text, version);
        } catch (const CompileError& error) {
            std::string message = error.what();
            const std::string folderName = folder.path().string() + "/";
            for (size_t at; (at = message.find(folderName)) != std::string::npos;) message.erase(at, folderName.size());
            return message;
        }
        return "(compiled)";
    }
    const ReflectedResource& resource(const CompiledShader& shader, const std::string& name) {
        for (const auto& resource : shader.reflection.resources)
            if (resource.name == name) return resource;
        throw std::runtime_error("no resource " + name);
    }
    testing::TempFolder folder;
};

constexpr const char* kEntry = "[numthreads(1, 1, 1)]\nvoid main(uint3 id : SV_DispatchThreadID) { Out[id.x] = f(id.x); }\n";

TEST_F(Hlsl2021, SelectEnumAndNamespaceCompile) {
    const auto shader = compile(std::string("namespace Colour {\nenum class Space : uint { Linear, Srgb };\n"
                                            "float3 toLinear(float3 c) { return select(c <= 0.04045, c / 12.92, "
                                            "pow((c + 0.055) / 1.055, 2.4)); }\n}\n"
                                            "RWStructuredBuffer<float3> Out : register(u0);\n"
                                            "float3 f(uint i) { return Colour::toLinear(i) * (uint)Colour::Space::Srgb; }\n") +
                                kEntry);
    EXPECT_EQ(resource(shader, "Out").location.binding, 96u);
}

TEST_F(Hlsl2021, Hlsl2018LowersEnumsAsDxcTakesThem) {
    // Enums are older than HLSL 2021: DXC takes them under -HV 2018 too (glslang alone says
    // "'enum' : Reserved word").
    EXPECT_NO_THROW(compile(std::string("RWStructuredBuffer<float> Out;\nenum E { A = 2 };\nfloat f(uint i) { return A; }\n") + kEntry,
                            lowering::HlslVersion::Hlsl2018));
}

TEST_F(Hlsl2021, AnErrorAfterALoweredConstructPointsAtTheUsersFileAndLine) {
    folder.write("colour.hlsli", "enum class Space { Linear };\n\nfloat g() { return undefinedThing; }\n");
    EXPECT_EQ(errorOf(std::string("#include \"colour.hlsli\"\nRWStructuredBuffer<float> Out;\nfloat f(uint i) { return g(); }\n") + kEntry),
              "In file included from shader.hlsl:1:\ncolour.hlsli:3:20: error: 'undefinedThing' is not declared where it is used "
              "(glslang: 'undefinedThing' : unknown variable)");
}

TEST_F(Hlsl2021, ALoweringErrorNamesTheConstructAndItsPlace) {
    EXPECT_EQ(errorOf("RWStructuredBuffer<float> Out;\ntemplate <typename T = float> T f(T x) { return x; }\n"),
              "shader.hlsl:2:12: error: a template parameter the kit cannot instantiate (a default argument, or a template "
              "template parameter): write 'typename T' or a constant such as 'uint N'");
}

// Before, glslang's binding from the attribute was taken for a register and shifted: binding
// 101 of set 1, and two attributed resources "clashed".
TEST_F(Hlsl2021, VulkanBindingWinsOverTheRegisterRule) {
    const auto shader = compile(std::string("[[vk::binding(5, 1)]] RWStructuredBuffer<float> Out;\n"
                                            "[[vk::binding(5, 0)]] RWStructuredBuffer<float> Other : register(u3);\n"
                                            "RWStructuredBuffer<float> Derived;\n"
                                            "float f(uint i) { return Other[i] + Derived[i]; }\n") + kEntry);
    const auto& out = resource(shader, "Out").location;
    EXPECT_EQ(out.set, 1u);
    EXPECT_EQ(out.binding, 5u);
    EXPECT_TRUE(out.vulkanBinding);
    EXPECT_EQ(resource(shader, "Other").location.binding, 5u);
    EXPECT_EQ(resource(shader, "Other").location.set, 0u);
    EXPECT_EQ(resource(shader, "Derived").location.registerName(), "u0");
    EXPECT_EQ(resource(shader, "Derived").location.binding, 96u);
}

TEST_F(Hlsl2021, AnExplicitBindingOnADerivedOneIsAnError) {
    EXPECT_EQ(errorOf(std::string("[[vk::binding(96)]] RWStructuredBuffer<float> Out;\n"
                                  "RWStructuredBuffer<float> Derived : register(u0);\n"
                                  "float f(uint i) { return Derived[i]; }\n") + kEntry),
              "shader.hlsl: error: 'Out' ([[vk::binding]]) and 'Derived' (register u0, space0) are both on set 0, binding 96");
}

// In Vulkan an array of resources is one binding; the kit once reserved a binding per element
// and called binding 1 after an array at binding 0 a clash.
TEST_F(Hlsl2021, AVulkanBindingOnAnArrayTakesOneBinding) {
    const auto shader = compile(std::string("[[vk::binding(0)]] RWTexture2D<float4> Mips[13];\n"
                                            "[[vk::binding(1)]] RWStructuredBuffer<float> Out;\n"
                                            "float f(uint i) { Mips[i][uint2(0, 0)] = 1; return 0; }\n") + kEntry);
    EXPECT_EQ(resource(shader, "Mips").location.binding, 0u);
    EXPECT_EQ(resource(shader, "Mips").location.count, 13u);
    EXPECT_EQ(resource(shader, "Out").location.binding, 1u);
    EXPECT_EQ(errorOf(std::string("[[vk::binding(0)]] RWTexture2D<float4> Mips[13];\n"
                                  "[[vk::binding(0)]] RWStructuredBuffer<float> Out;\n"
                                  "float f(uint i) { Mips[i][uint2(0, 0)] = 1; return 0; }\n") + kEntry),
              "shader.hlsl: error: 'Mips' ([[vk::binding]]) and 'Out' ([[vk::binding]]) are both on set 0, binding 0");
}

// The HLSL form gives resources bound by [[vk::binding]] registers of their own: the array
// takes u1-u13 after Out's u0 (both were u0 before).
TEST_F(Hlsl2021, TheHlslFormGivesVulkanBoundResourcesDistinctRegisters) {
    const auto shader = compile(std::string("[[vk::binding(0)]] RWTexture2D<float4> Mips[13];\n"
                                            "[[vk::binding(1)]] RWStructuredBuffer<float> Out;\n"
                                            "RWStructuredBuffer<float> Derived : register(u1, space1);\n"
                                            "[[vk::binding(2, 1)]] RWStructuredBuffer<float> Other;\n"
                                            "float f(uint i) { Mips[i][uint2(0, 0)] = 1; return Derived[i] + Other[i]; }\n") +
                                kEntry);
    const auto hlsl = crossCompileShader(shader, CrossTarget::Hlsl).source;
    EXPECT_NE(hlsl.find("RWByteAddressBuffer Out : register(u0, space0);"), std::string::npos) << hlsl;
    EXPECT_NE(hlsl.find("RWTexture2D<float4> Mips[13] : register(u1, space0);"), std::string::npos) << hlsl;
    EXPECT_NE(hlsl.find("RWByteAddressBuffer Derived : register(u1, space1);"), std::string::npos) << hlsl;
    EXPECT_NE(hlsl.find("RWByteAddressBuffer Other : register(u0, space1);"), std::string::npos) << hlsl;
}

TEST_F(Hlsl2021, ImageFormatAttributeSetsTheFormat) {
    const auto shader = compile(std::string("[[vk::image_format(\"r11g11b10f\")]] RWTexture2D<float4> Img;\n"
                                            "RWStructuredBuffer<float> Out;\n"
                                            "float f(uint i) { Img[uint2(i, 0)] = 1; return 0; }\n") + kEntry);
    EXPECT_EQ(resource(shader, "Img").format, "r11f_g11f_b10f");
    EXPECT_TRUE(shader.warnings.empty()) << shader.warnings.front();
}

TEST_F(Hlsl2021, AnUnknownImageFormatAttributeIsRefused) {
    EXPECT_EQ(errorOf(std::string("[[vk::image_format(\"rgb9e5\")]] RWTexture2D<float4> Img;\n"
                                  "RWStructuredBuffer<float> Out;\nfloat f(uint i) { Img[uint2(i, 0)] = 1; return 0; }\n") + kEntry),
              "shader.hlsl: error: [[vk::image_format(\"rgb9e5\")]] on 'Img' is not a storage image format");
}

TEST_F(Hlsl2021, PushConstantOnAPlainStructIsAPushConstantBlock) {
    const auto shader = compile(std::string("struct P { float scale; };\n[[vk::push_constant]] P pc;\n"
                                            "RWStructuredBuffer<float> Out;\nfloat f(uint i) { return pc.scale; }\n") + kEntry);
    EXPECT_EQ(shader.reflection.pushConstantBlock, "pc");
    EXPECT_EQ(shader.reflection.pushConstants.size(), 1u);
}

TEST_F(Hlsl2021, AnAttributeTheKitDoesNotHonourIsAWarning) {
    const auto shader = compile(std::string("[[vk::combinedImageSampler]] RWStructuredBuffer<float> Out;\n"
                                            "float f(uint i) { return 0; }\n") + kEntry);
    ASSERT_FALSE(shader.warnings.empty());
    EXPECT_NE(shader.warnings.front().find("[[vk::combinedImageSampler]] is not honoured by the kit"), std::string::npos)
        << shader.warnings.front();
}

TEST_F(Hlsl2021, SixteenBitTypesAreSixteenBitsWideWithTheSwitch) {
    CompileOptions options;
    options.source = folder.write("half.hlsl", std::string("RWStructuredBuffer<float> Out;\n"
                                                           "float f(uint i) { float16_t2 v = float16_t2(float16_t(1.5), float16_t(2.0)); "
                                                           "min16float m = (min16float)2.5; float r = v.y * m; return r; }\n") +
                                                   kEntry);
    options.enable16BitTypes = true;
    const auto shader = compileShader(options);
    EXPECT_TRUE(shader.warnings.empty());
    EXPECT_NE(disassembleSpirv(shader.spirv).find("OpTypeFloat 16"), std::string::npos);
    options.enable16BitTypes = false;
    EXPECT_THROW(compileShader(options), CompileError); // float16_t needs the switch
}

// glslang converts no float literal to a half vector's components; its first error had no place.
TEST_F(Hlsl2021, AConversionGlslangLacksIsReportedAtItsLine) {
    CompileOptions options;
    options.source = folder.write("half.hlsl", "RWStructuredBuffer<float> Out;\nfloat f(uint i) { half2 v = half2(1.5, 2); return v.y; }\n");
    options.enable16BitTypes = true;
    try {
        compileShader(options);
        FAIL() << "compiled";
    } catch (const CompileError& error) {
        EXPECT_EQ(std::string(error.what()),
                  options.source.string() + ":2:1: error: a constructor or cast whose arguments glslang's HLSL frontend does not "
                                            "convert to its type (an integer or a 32-bit value to a 16-bit float): convert each "
                                            "argument to the type's scalar first (glslang: ' const 2-component vector of "
                                            "float16_t' : cannot construct with these arguments)");
    }
}

// A [numthreads] past Direct3D's limits is refused at compile time, as DXC refuses it.
TEST_F(Hlsl2021, AThreadGroupPastDirect3DsLimitsIsRefusedByName) {
    const auto shader = [](const std::string& threads) {
        return "RWStructuredBuffer<uint> Out;\n[numthreads(" + threads + ")]\nvoid main(uint3 id : SV_DispatchThreadID) { Out[id.x] = id.x; }\n";
    };
    EXPECT_EQ(errorOf(shader("0, 1, 1")), "shader.hlsl: error: [numthreads(0, 1, 1)] on 'main': every dimension must be at least "
                                          "1 (Direct3D's limit, which DXC holds shaders to)");
    EXPECT_EQ(errorOf(shader("1024, 1024, 64")), "shader.hlsl: error: [numthreads(1024, 1024, 64)] on 'main': 67108864 threads "
                                                 "in a group, where at most 1024 are allowed (Direct3D's limit, which DXC holds "
                                                 "shaders to)");
    EXPECT_NE(errorOf(shader("1, 1, 65")).find("z is at most 64"), std::string::npos);
    EXPECT_NE(errorOf(shader("2048, 1, 1")).find("x and y are at most 1024"), std::string::npos);
    EXPECT_NO_THROW(compile(shader("1024, 1, 1")));
    EXPECT_NO_THROW(compile(shader("32, 32, 1")));
    EXPECT_NO_THROW(compile(shader("1, 1, 64")));
}

} // namespace
} // namespace iblkit::compiler
