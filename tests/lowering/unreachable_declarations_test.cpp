// What the entry point never reaches is dropped when it is a function or holds a feature glslang
// lacks; what it reaches stays, and a lacking feature it reaches is still refused by name.
#include "lowering.hpp"
#include "lowering_error.hpp"

#include <gtest/gtest.h>

namespace iblkit::lowering {
namespace {

std::string pruned(const std::string& text, const std::string& entry = "main") {
    return lowerHlsl(text, "a.hlsl", HlslVersion::Hlsl2021, false, entry).text;
}

const std::string kSharedHeader = "RaytracingAccelerationStructure Bvh[] : register(t7, space1);\n"
                                  "RaytracingAccelerationStructure GetBvh(uint i) { return Bvh[i]; }\n"
                                  "float Unused(float x) { return x; }\n"
                                  "Texture2D Unbound : register(t3);\n"
                                  "float Square(float x) { return x * x; }\n";

TEST(UnreachableDeclarations, RayTracingAndFunctionsTheEntryPointNeverReachesAreDropped) {
    const auto text = pruned(kSharedHeader + "[numthreads(1, 1, 1)] void main() { float y = Square(2.0); }\n");
    EXPECT_EQ(text.find("Raytracing"), std::string::npos);
    EXPECT_EQ(text.find("Unused"), std::string::npos);
    EXPECT_NE(text.find("Square"), std::string::npos);
    // A resource glslang can express stays, used or not: the reflection lists it.
    EXPECT_NE(text.find("Unbound"), std::string::npos);
    // Lines keep their numbers: the dropped lines' newlines stay.
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 6);
}

TEST(UnreachableDeclarations, WhatTheEntryPointReachesThroughOthersStays) {
    const auto text = pruned("float Inner(float x) { return x; }\nfloat Outer(float x) { return Inner(x); }\n"
                              "cbuffer Params { float Scale; }\nfloat UsesScale() { return Scale; }\n"
                              "float4 main() : SV_Target { return Outer(UsesScale()); }\n");
    for (const char* name : {"Inner", "Outer", "UsesScale"}) EXPECT_NE(text.find(std::string(name) + "("), std::string::npos) << name;
}

TEST(UnreachableDeclarations, AStructWithMemberFunctionsIsAFunctionToReach) {
    // Unreached, it goes with what only its member functions call; reached, both stay.
    const std::string helpers = "float Dir(float x) { return x; }\nstruct Light { float a; float Sample() { return Dir(a); } };\n";
    EXPECT_EQ(pruned(helpers + "float main() : SV_Target { return 1; }"), "\n\nfloat main() : SV_Target { return 1; }");
    const std::string reached = helpers + "float main() : SV_Target { Light l; l.a = 1; return l.Sample(); }";
    EXPECT_EQ(pruned(reached), reached);
    // A prototype goes with its function.
    EXPECT_EQ(pruned("float Late();\nfloat Late() { return 2; }\nfloat main() : SV_Target { return 1; }"),
              "\n\nfloat main() : SV_Target { return 1; }");
    // A struct without member functions stays, reached or not, as types and resources do.
    EXPECT_EQ(pruned("struct Plain { float a; };\nfloat main() : SV_Target { return 1; }"),
              "struct Plain { float a; };\nfloat main() : SV_Target { return 1; }");
}

TEST(UnreachableDeclarations, APatchConstantFunctionNamedInAnAttributeIsReached) {
    const auto text = pruned("float Helper() { return 1; }\nvoid Patch() { Helper(); }\n"
                              "[patchconstantfunc(\"Patch\")] void HS() {}\n", "HS");
    EXPECT_NE(text.find("Helper()"), std::string::npos);
}

TEST(UnreachableDeclarations, RayTracingTheEntryPointReachesIsRefused) {
    try {
        pruned("RaytracingAccelerationStructure Bvh : register(t0);\n"
                "[numthreads(1, 1, 1)] void main() { RaytracingAccelerationStructure b = Bvh; }\n");
        FAIL() << "not refused";
    } catch (const LoweringError& error) {
        EXPECT_NE(std::string(error.what()).find("ray tracing ('RaytracingAccelerationStructure')"), std::string::npos);
    }
}

TEST(NonUniformResourceIndex, BecomesTheBareIndexUnlessTheShaderDefinesItsOwn) {
    EXPECT_EQ(pruned("float4 main() : SV_Target { return T[NonUniformResourceIndex(i + 1)].Load(0); }"),
              "float4 main() : SV_Target { return T[(i + 1)].Load(0); }");
    const std::string own = "uint NonUniformResourceIndex(uint i) { return i; }\n"
                            "float4 main() : SV_Target { return T[NonUniformResourceIndex(i)].Load(0); }";
    EXPECT_EQ(pruned(own), own);
}

TEST(UnreachableDeclarations, WithoutTheEntryPointNothingIsDropped) {
    const std::string text = "float Unused(float x) { return x; }\n";
    EXPECT_EQ(pruned(text, "missing"), text);
    EXPECT_EQ(pruned(text, ""), text);
}

} // namespace
} // namespace iblkit::lowering
