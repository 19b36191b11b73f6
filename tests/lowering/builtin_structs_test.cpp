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

} // namespace
} // namespace iblkit::lowering
