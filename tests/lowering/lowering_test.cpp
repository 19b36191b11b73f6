// The HLSL 2021 lowering on the text glslang's preprocessor gives: what each construct becomes,
// that every line keeps its number, and that what cannot be lowered is refused by name.
// (That the lowered shaders compute what DXC's would is the porting corpus's test.)
#include "lowering.hpp"
#include "lowering_error.hpp"
#include "lowering_error_of.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace iblkit::lowering {
namespace {

std::string lowered(const std::string& text) { return lowerHlsl(text, "a.hlsl", HlslVersion::Hlsl2021).text; }

size_t lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

TEST(Lowering, AShaderWithoutHlsl2021IsUnchanged) {
    const std::string text = "float4 main(float4 p : SV_Position) : SV_Target { return p.x > 0 ? p : -p; }\n";
    const auto result = lowerHlsl(text, "a.hlsl", HlslVersion::Hlsl2021);
    EXPECT_FALSE(result.changed);
    EXPECT_EQ(result.text, text);
}

TEST(Lowering, SelectAndOrBecomeComponentWiseOperators) {
    EXPECT_EQ(lowered("x = select(c <= 0.5, a, f(b, 2));"), "x = ((c <= 0.5) ? (a) : (f(b, 2)));");
    EXPECT_EQ(lowered("m = and(a, or(b, c));"), "m = ((a) && (((b) || (c))));");
    EXPECT_EQ(lowered("y = select(select(p, q, r), 1, 2);"), "y = ((((p) ? (q) : (r))) ? (1) : (2));");
}

TEST(Lowering, AShadersOwnSelectFunctionIsCalledAsWritten) {
    const std::string text = "float select(float a, float b) { return a; }\nfloat g() { return select(1, 2); }";
    EXPECT_EQ(lowered(text), text);
}

TEST(Lowering, SelectWithTheWrongArgumentCountIsRefused) {
    EXPECT_EQ(errorOf("\nx = select(a, b);"), "a.hlsl:2:5: error: select takes 3 arguments, not 2");
}

TEST(Lowering, AnUnscopedEnumBecomesATypedefAndConstants) {
    EXPECT_EQ(lowered("enum Mode { A, B = 4, C };\nMode m = C; int n = Mode::B;"),
              "typedef int Mode; static const Mode A = 0; static const Mode B = 4; static const Mode C = B + 1;\n"
              "Mode m = C; int n = B;");
}

TEST(Lowering, AnUnscopedEnumeratorValuedFromAnEarlierOneKeepsItsGlobalName) {
    EXPECT_EQ(lowered("enum E { A = 1, B = A + 1 };\nenum { X = 2, Y = X * B };"),
              "typedef int E; static const E A = 1; static const E B = A + 1;\n"
              " static const int X = 2; static const int Y = X * B;");
}

TEST(Lowering, AScopedEnumKeepsItsTypeAndQualifiesItsNames) {
    EXPECT_EQ(lowered("enum class Space : uint { Linear, Srgb = Linear + 3 };\nuint s = (uint)Space::Srgb;"),
              "typedef uint Space; static const Space Space__Linear = 0; static const Space Space__Srgb = Space__Linear + 3;\n"
              "uint s = (uint)Space__Srgb;");
}

TEST(Lowering, AnEnumOverSeveralLinesKeepsEveryLaterLine) {
    const std::string text = "enum Colour\n{\n    Red,\n    Green = 5,\n};\nColour c;\n";
    const auto result = lowered(text);
    EXPECT_EQ(lines(result), lines(text));
    EXPECT_NE(result.find("\nColour c;"), std::string::npos) << result;
}

TEST(Lowering, AnUnknownEnumeratorIsRefused) {
    EXPECT_EQ(errorOf("enum class E { A };\nuint x = E::B;"), "a.hlsl:2:13: error: 'B' is not an enumerator of enum 'E'");
}

TEST(Lowering, NamespaceMembersAreRenamedAtEveryUse) {
    const std::string text = "namespace Colour {\nstatic const float Gamma = 2.4;\n"
                             "float3 toLinear(float3 c) { return pow(c, Gamma); }\n}\n"
                             "float3 f(float3 c) { return Colour::toLinear(c) * Colour::Gamma; }";
    EXPECT_EQ(lowered(text), "\nstatic const float Colour__Gamma = 2.4;\n"
                             "float3 Colour__toLinear(float3 c) { return pow(c, Colour__Gamma); }\n\n"
                             "float3 f(float3 c) { return Colour__toLinear(c) * Colour__Gamma; }");
}

TEST(Lowering, NestedNamespacesAndTheGlobalScope) {
    const std::string text = "float g;\nnamespace A { namespace B { float g; float h() { return g + ::g; } } "
                             "float k() { return B::g; } }\nfloat m() { return A::B::h() + A::k(); }";
    EXPECT_EQ(lowered(text), "float g;\n float A__B__g; float A__B__h() { return A__B__g + g; } "
                             "float A__k() { return A__B__g; }\nfloat m() { return A__B__h() + A__k(); }");
}

TEST(Lowering, LocalsAndParametersHideNamespaceMembers) {
    const std::string text = "namespace N { float x; float f(float x) { return x; } float g() { float x = 1; return x; } "
                             "float h() { return x; } }";
    EXPECT_EQ(lowered(text), " float N__x; float N__f(float x) { return x; } float N__g() { float x = 1; return x; } "
                             "float N__h() { return N__x; }");
}

TEST(Lowering, StructsAndCbuffersInANamespace) {
    const std::string text = "namespace L { struct Light { float3 d; }; cbuffer Frame { Light sun; }; }\n"
                             "float3 f() { return L::sun.d; }";
    EXPECT_EQ(lowered(text), " struct L__Light { float3 d; }; cbuffer L__Frame { L__Light L__sun; };\n"
                             "float3 f() { return L__sun.d; }");
}

TEST(Lowering, AnEnumInANamespace) {
    const std::string text = "namespace P { enum class Mode { Fast, Exact }; }\nuint m = (uint)P::Mode::Exact;";
    EXPECT_EQ(lowered(text), " typedef int P__Mode; static const P__Mode P__Mode__Fast = 0; "
                             "static const P__Mode P__Mode__Exact = P__Mode__Fast + 1;\nuint m = (uint)P__Mode__Exact;");
}

TEST(Lowering, UsingAnAliasIsATypedef) {
    EXPECT_EQ(lowered("using Colour = float3;\nColour c;"), "typedef float3 Colour;\nColour c;");
}

TEST(Lowering, WhatCannotBeLoweredIsRefusedByName) {
    EXPECT_EQ(errorOf("\n  template <> float twice(float x) { return x * 2; }"),
              "a.hlsl:2:3: error: an explicit specialization (template <>) cannot be lowered: give the specialized function its own name");
    EXPECT_EQ(errorOf("struct S { uint a : 4; uint b : 28; };"),
              "a.hlsl:1:17: error: the bitfield 'a : 4' cannot be lowered: use a whole member and shift and mask it");
    EXPECT_EQ(errorOf("S operator+(S a, S b);"),
              "a.hlsl:1:3: error: operator overloading ('operator+') cannot be lowered: write a named function");
    EXPECT_EQ(errorOf("using namespace N;"), "a.hlsl:1:1: error: 'using namespace' cannot be lowered: qualify the names (N::name)");
    // A named struct's enum moves to a namespace of its name (struct_scope.hpp); an unnamed one has none.
    EXPECT_EQ(errorOf("struct { enum E { A }; } s;"), "a.hlsl:1:10: error: an enum inside a struct cannot be lowered: declare it outside");
}

TEST(Lowering, ASemanticIsNoBitfield) {
    const std::string text = "struct V { float4 p : SV_Position; float2 uv : TEXCOORD0; };\nx = c ? a : 1;";
    EXPECT_EQ(lowered(text), text);
}

TEST(Lowering, ErrorsNameTheFileAndLineOfTheLineDirective) {
    EXPECT_EQ(errorOf("#line 7 \"inc/colour.hlsli\"\nfloat f() { return select(1); }"),
              "inc/colour.hlsli:7:20: error: select takes 3 arguments, not 1");
}

TEST(Lowering, Hlsl2018KeepsSelectAndOrAsNamesButLowersEnums) {
    // and, or and select are HLSL 2021's; enums and namespaces are older, and DXC takes them
    // under -HV 2018.
    const std::string text = "bool2 and(bool2 a, bool2 b);";
    EXPECT_EQ(lowerHlsl(text, "a.hlsl", HlslVersion::Hlsl2018).text, text);
    const auto result = lowerHlsl("enum X { A };\nint f() { return A; }", "a.hlsl", HlslVersion::Hlsl2018);
    EXPECT_EQ(result.edits, std::vector<std::string>{"enums"});
}

TEST(SixteenBitTypes, DxcsExplicitTypesTakeGlslangsNames) {
    const auto result = lowerHlsl("float16_t a; float16_t3x3 m; int16_t2 i; uint16_t u; s.float16_t;", "a.hlsl",
                                  HlslVersion::Hlsl2021, true);
    EXPECT_EQ(result.text, "half a; half3x3 m; min16int2 i; min16uint u; s.float16_t;");
    EXPECT_TRUE(result.warnings.empty());
}

TEST(SixteenBitTypes, WithoutTheSwitchTheyAreRefusedAsDxcRefusesThem) {
    EXPECT_EQ(errorOf("float x;\n  uint16_t2 u;"), "a.hlsl:2:3: error: 'uint16_t2' is a 16-bit type: compile with -enable-16bit-types");
}

TEST(SixteenBitTypes, MinimumPrecisionAt32BitsIsAWarning) {
    const auto result = lowerHlsl("min16float a; min16float2 b; min16uint c; half d;", "a.hlsl", HlslVersion::Hlsl2021);
    ASSERT_EQ(result.warnings.size(), 1u);
    EXPECT_EQ(result.warnings[0], "a.hlsl: warning: min16float, min16float2, min16uint compiled at 32 bits (minimum "
                                  "precision without -enable-16bit-types; docs/compiler.md)");
    EXPECT_TRUE(lowerHlsl("min16float a;", "a.hlsl", HlslVersion::Hlsl2021, true).warnings.empty());
}

TEST(VulkanAttributes, BindingsAreReadByResourceName) {
    const auto result = lowerHlsl("[[vk::binding(5, 1)]] RWTexture2D<float4> Img : register(u0);\n"
                                  "[[vk::binding(2)]] cbuffer Params { float4 k; };\n"
                                  "[[vk::binding(3, 2)]] ConstantBuffer<P> pc;",
                                  "a.hlsl", HlslVersion::Hlsl2021);
    ASSERT_EQ(result.vulkan.bindings.size(), 3u);
    EXPECT_EQ(result.vulkan.bindings.at("Img").binding, 5u);
    EXPECT_EQ(result.vulkan.bindings.at("Img").set, 1u);
    EXPECT_EQ(result.vulkan.bindings.at("Params").binding, 2u);
    EXPECT_EQ(result.vulkan.bindings.at("Params").set, 0u);
    EXPECT_EQ(result.vulkan.bindings.at("pc").set, 2u);
    EXPECT_FALSE(result.changed); // glslang reads vk::binding itself; the kit decides what wins
}

TEST(VulkanAttributes, ImageFormatIsTakenAndDropped) {
    const auto result = lowerHlsl("[[vk::image_format(\"rgba8\")]] RWTexture2D<float4> Img;\n"
                                  "[[vk::binding(1), vk::image_format(\"r32f\")]] RWTexture2D<float> Depth;",
                                  "a.hlsl", HlslVersion::Hlsl2021);
    EXPECT_EQ(result.text, " RWTexture2D<float4> Img;\n[[vk::binding(1)]] RWTexture2D<float> Depth;");
    EXPECT_EQ(result.vulkan.imageFormats.at("Img"), "rgba8");
    EXPECT_EQ(result.vulkan.imageFormats.at("Depth"), "r32f");
}

TEST(VulkanAttributes, PushConstantOnAPlainStructBecomesAConstantBuffer) {
    EXPECT_EQ(lowered("struct P { float s; };\n[[vk::push_constant]] P pc;"),
              "struct P { float s; };\n[[vk::push_constant]] ConstantBuffer<P> pc;");
    EXPECT_EQ(lowered("[[vk::push_constant]] ConstantBuffer<P> pc;"), "[[vk::push_constant]] ConstantBuffer<P> pc;");
}

TEST(VulkanAttributes, AnAttributeTheKitDoesNotHonourIsAWarning) {
    const auto result = lowerHlsl("[[vk::combinedImageSampler]] Texture2D t;", "a.hlsl", HlslVersion::Hlsl2021);
    ASSERT_EQ(result.warnings.size(), 1u);
    EXPECT_EQ(result.warnings[0], "a.hlsl:1:7: warning: [[vk::combinedImageSampler]] is not honoured by the kit "
                                         "(it honours vk::binding, image_format, push_constant, constant_id and location)");
}

TEST(VulkanAttributes, ABindingThatIsNoNumberIsRefused) {
    EXPECT_EQ(errorOf("[[vk::binding(X)]] Texture2D t;"), "a.hlsl:1:15: error: [[vk::binding]] takes whole numbers, not 'X'");
}

} // namespace
} // namespace iblkit::lowering
