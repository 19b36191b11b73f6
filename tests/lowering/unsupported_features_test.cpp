// What glslang's HLSL frontend lacks is refused by name and place in every HLSL version, and each
// lowering pass that changed the shader is named among its edits.
#include "lowering.hpp"
#include "lowering_error.hpp"
#include "lowering_error_of.hpp"

#include <gtest/gtest.h>

namespace iblkit::lowering {
namespace {

TEST(UnsupportedFeatures, EachIsRefusedByNameAndPlaceInEveryVersion) {
    for (const auto version : {HlslVersion::Hlsl2018, HlslVersion::Hlsl2021}) {
        EXPECT_EQ(errorOf("interface IShape { float area(); };", version),
                  "a.hlsl:1:1: error: an interface is not supported by glslang's HLSL frontend: write a struct with "
                  "member functions and call them directly");
        EXPECT_NE(errorOf("RaytracingAccelerationStructure Scene;", version).find("a.hlsl:1:1: error: ray tracing"),
                  std::string::npos);
        EXPECT_NE(errorOf("void f() { RWBuffer<float> b = ResourceDescriptorHeap[0]; }", version).find("dynamic resources"),
                  std::string::npos);
        EXPECT_NE(errorOf("uint f() { return pack_u8(uint4(1, 2, 3, 4)); }", version).find("a.hlsl:1:19: error: the Shader "
                                                                                         "Model 6.6 intrinsic 'pack_u8'"),
                  std::string::npos);
        EXPECT_NE(errorOf("uint f(uint x) { return WaveMatch(x).x; }", version).find("'WaveMatch'"), std::string::npos);
        EXPECT_NE(errorOf("float f() { return dot2add(half2(1, 2), half2(3, 4), 1.0); }", version).find("'dot2add'"),
                  std::string::npos);
    }
}

TEST(UnsupportedFeatures, SixtyFourBitIntegersOtherThanTheUint64ScalarAreRefused) {
    EXPECT_EQ(errorOf("void f() { uint64_t a = 1; a <<= 40; }"), "(no error)");
    EXPECT_NE(errorOf("void f() { int64_t a = 1; }").find("'int64_t' is not supported"), std::string::npos);
    EXPECT_NE(errorOf("void f() { uint64_t2 a; }").find("'uint64_t2' is not supported"), std::string::npos);
    EXPECT_NE(errorOf("void f() { int64_t3x3 a; }").find("'int64_t3x3'"), std::string::npos);
    EXPECT_EQ(errorOf("void f() { uint uint64_total = 1; }"), "(no error)") << "a name that only starts like the type";
}

TEST(UnsupportedFeatures, ALiteralConvertedToUint64IsRefusedWithTheWayAround) {
    const std::string expected = "a literal converted to uint64_t ('100000') is not supported by glslang's HLSL frontend: "
                                 "assign it to a uint64_t variable first";
    EXPECT_EQ(errorOf("void f() { uint64_t a = (uint64_t)100000 * 3; }"), "a.hlsl:1:26: error: " + expected);
    EXPECT_EQ(errorOf("void f() { uint64_t a = uint64_t(100000) * 3; }"), "a.hlsl:1:25: error: " + expected);
    EXPECT_EQ(errorOf("void f(uint x) { uint64_t a = (uint64_t)x * 3; }"), "(no error)") << "a variable converts fine";
}

TEST(UnsupportedFeatures, AnIntrinsicTheShaderDefinesItselfIsItsOwn) {
    EXPECT_EQ(errorOf("uint pack_u8(uint4 v) { return v.x | v.y << 8 | v.z << 16 | v.w << 24; }\n"
                      "uint f() { return pack_u8(uint4(1, 2, 3, 4)); }"),
              "(no error)");
    EXPECT_EQ(errorOf("float dot2add(half2 a, half2 b, float c);\nfloat f() { return 1; }"),
              "a.hlsl:1:7: error: the Shader Model 6.4 intrinsic 'dot2add' is not supported by glslang's HLSL frontend: "
              "write the dot product")
        << "a declaration without a body defines nothing";
}

TEST(UnsupportedFeatures, NoUseOfANameLooksLikeItsDefinition) {
    EXPECT_NE(errorOf("static const int64_t K = 1;").find("'int64_t' is not supported"), std::string::npos);
    EXPECT_NE(errorOf("bool f(float n) { return n > dot2add(half2(1, 2), half2(3, 4), 1.0); }").find("'dot2add'"),
              std::string::npos);
    EXPECT_NE(errorOf("int64_t int64_t(int64_t x) { return x; }").find("'int64_t' is not supported"), std::string::npos)
        << "a type is never the shader's own";
}

TEST(LoweringEdits, EachPassThatChangedTheShaderIsNamed) {
    const auto edits = [](const std::string& text, bool sixteen = false) {
        return lowerHlsl(text, "a.hlsl", HlslVersion::Hlsl2021, sixteen).edits;
    };
    EXPECT_TRUE(edits("float f(float x) { return x > 0 ? x : -x; }").empty());
    EXPECT_EQ(edits("float4 f(bool4 c, float4 a) { return select(c, a, -a); }"), std::vector<std::string>{"select-and-or"});
    EXPECT_EQ(edits("enum E { A, B }; E f() { return B; }"), std::vector<std::string>{"enums"});
    EXPECT_EQ(edits("namespace N { float g() { return 1; } } float f() { return N::g(); }"),
              std::vector<std::string>{"namespaces"});
    EXPECT_EQ(edits("float16_t f(float16_t x) { return x; }", true), std::vector<std::string>{"explicit-width-types"});
    EXPECT_EQ(edits("[[vk::binding(2, 1)]] RWStructuredBuffer<uint> B;"), std::vector<std::string>{"vk-binding"});
    EXPECT_EQ(edits("[[vk::image_format(\"rgba8\")]] RWTexture2D<float4> T;"), std::vector<std::string>{"vk-image-format"});
    EXPECT_EQ(edits("struct S { float a; }; [[vk::push_constant]] S P;"), std::vector<std::string>{"vk-push-constant"});
    EXPECT_TRUE(edits("[[vk::push_constant]] ConstantBuffer<S> P;").empty()) << "glslang's own push-constant block";
}

} // namespace
} // namespace iblkit::lowering
