// DXR's plain structs are declared where a shader uses them without declaring them.
#include "lowering.hpp"

#include <gtest/gtest.h>

namespace iblkit::lowering {
namespace {

std::string declared(const std::string& text) { return lowerHlsl(text, "a.hlsl", HlslVersion::Hlsl2021).text; }

TEST(BuiltinStructs, RayDescIsDeclaredOnTheFirstLine) {
    EXPECT_EQ(declared("#line 1 \"a.hlsl\"\nRayDesc f() { RayDesc r; return r; }\nint g;"),
              "#line 1 \"a.hlsl\"\nstruct RayDesc { float3 Origin ; float TMin ; float3 Direction ; float TMax ; } ; RayDesc f() "
              "{ RayDesc r; return r; }\nint g;");
}

TEST(BuiltinStructs, AShadersOwnDeclarationAndShadersWithoutOneStay) {
    for (const std::string text : {"struct RayDesc { float3 o; };\nRayDesc f();", "float4 f() { return 0; }"})
        EXPECT_EQ(declared(text), text);
}

TEST(StructConversions, AStructReturnedAsOneOfTheSameMemberTypesIsConvertedMemberByMember) {
    const std::string structs = "struct A { float4 p : SV_Position; float2 uv : UV; };\nstruct B { float4 q : SV_Position; float2 t : T; };\n";
    EXPECT_EQ(declared(structs + "B f(A a) { return a; }"),
              structs + "B f(A a) { { B iblkit_converted_0 ; iblkit_converted_0 . q = a . p ; iblkit_converted_0 . t = a . uv ; "
                        "return iblkit_converted_0 ; } }");
    // Members of other types, and a value of the return type, stay as they are.
    for (const std::string text : {"struct A { float4 p; };\nstruct C { float3 p; };\nC f(A a) { return a; }",
                                   "struct A { float4 p; };\nstruct C { float4 p; };\nC f(C c) { return c; }"})
        EXPECT_EQ(declared(text), text);
}

} // namespace
} // namespace iblkit::lowering
