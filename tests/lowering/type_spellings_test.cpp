// vector<T, N>, matrix<T, R, C> and `unsigned int` as glslang's HLSL frontend reads them.
#include "lowering.hpp"

#include <gtest/gtest.h>

namespace iblkit::lowering {
namespace {

std::string spelled(const std::string& text, bool sixteenBit = false) {
    return lowerHlsl(text, "a.hlsl", HlslVersion::Hlsl2021, sixteenBit).text;
}

TEST(TypeSpellings, VectorAndMatrixTemplatesOfAnyScalarBecomeTheirShortNames) {
    EXPECT_EQ(spelled("typedef vector<min16float, 2> H2; typedef matrix<float, 3, 4> M;"),
              "typedef min16float2 H2; typedef float3x4 M;");
    // float16_t is lowered to half after its template is spelled out.
    EXPECT_EQ(spelled("vector<float16_t, 3> v;", true), "half3 v;");
}

TEST(TypeSpellings, TemplatesOfOtherTypesAndMembersNamedVectorAreKept) {
    const std::string text = "vector<MyType, 2> a; vector<float, N> b; s.vector; matrix<float, 5, 1> c;";
    EXPECT_EQ(spelled(text), text);
}

TEST(TypeSpellings, MinimumPrecisionMatricesAreHalfMatrices) {
    // glslang has min16float2 but no min16float3x3; half is min16float to it.
    EXPECT_EQ(spelled("typedef min16float3x3 M; min10float2x4 a; min16float3 v;"), "typedef half3x3 M; half2x4 a; min16float3 v;");
}

TEST(TypeSpellings, SwizzledLiteralsAreParenthesizedFloats) {
    EXPECT_EQ(spelled("float4 a = 1.xxxx; bool2 b = (i % 2.xx) == 0; float2 c = 0.5.rr; float d = 1.5e3;"),
              "float4 a = (1.0).xxxx; bool2 b = (i % (2.0).xx) == 0; float2 c = (0.5).rr; float d = 1.5e3;");
    // As glslang's preprocessor writes them.
    EXPECT_EQ(spelled("float4 a = 1. xxxx; float2 b = 2. xy;"), "float4 a = (1.0).xxxx; float2 b = (2.0).xy;");
}

TEST(TypeSpellings, UnsignedIntIsUint) {
    EXPECT_EQ(spelled("static const unsigned int a = 1; unsigned b;"), "static const uint a = 1; uint b;");
}

TEST(ExplicitWidthTypes, ThirtyTwoAndSixtyFourBitNamesNeedNoSwitch) {
    const auto result = lowerHlsl("float32_t2 a; int32_t b; uint32_t4 c; float64_t d; uint64_t e;", "a.hlsl", HlslVersion::Hlsl2021);
    EXPECT_EQ(result.text, "float2 a; int b; uint4 c; double d; uint64_t e;");
    EXPECT_EQ(result.edits, std::vector<std::string>{"explicit-width-types"});
}

} // namespace
} // namespace iblkit::lowering
