// A write to some components of a storage texel reads the texel, writes them, stores it back.
#include "lowering.hpp"

#include <gtest/gtest.h>

namespace iblkit::lowering {
namespace {

std::string texelWritesLowered(const std::string& text) { return lowerHlsl(text, "a.hlsl", HlslVersion::Hlsl2021).text; }

TEST(PartialTexelWrites, ReadModifyWriteWithTheCoordinatesOnce) {
    EXPECT_EQ(texelWritesLowered("RWTexture2DArray<float4> D;\nvoid f(uint3 c) { D[c].w = 1; }"),
              "RWTexture2DArray<float4> D;\nvoid f(uint3 c) { { uint3 iblkit_texel_at_0 = c ; float4 iblkit_texel_0 = D [ "
              "iblkit_texel_at_0 ] ; iblkit_texel_0 . w = 1 ; D [ iblkit_texel_at_0 ] = iblkit_texel_0 ; } }");
}

TEST(PartialTexelWrites, TakesParametersArraysDefaultTexelsAndCompoundAssignments) {
    const auto text = texelWritesLowered("void f(RWTexture1D<uint2> p, uint i) { p[i].y += 2; }");
    EXPECT_NE(text.find("uint iblkit_texel_at_0 = i ; uint2 iblkit_texel_0 = p [ iblkit_texel_at_0 ] ; iblkit_texel_0 . y += 2"),
              std::string::npos)
        << text;
    const auto array = texelWritesLowered("RWTexture2D T[4];\nvoid f(uint2 c) { if (c.x > 0) T[c.y][c].rg = 0; }");
    EXPECT_NE(array.find("if (c.x > 0) { uint2 iblkit_texel_at_0 = c ; float4 iblkit_texel_0 = T [ c . y ] [ iblkit_texel_at_0 ]"),
              std::string::npos)
        << array;
}

TEST(PartialTexelWrites, LeavesWholeTexelsBuffersAndIndicesWithSideEffects) {
    for (const std::string text :
         {"RWTexture2D<float4> D;\nvoid f(uint2 c) { D[c] = 1; }", "RWStructuredBuffer<S> B;\nvoid f(uint i) { B[i].x = 1; }",
          "RWTexture2D<float4> T[4];\nvoid f(uint2 c, uint i) { T[i++][c].x = 1; }",
          "RWTexture2D<float4> D;\nvoid f(uint2 c) { float y = D[c].x = 1; }"})
        EXPECT_EQ(texelWritesLowered(text), text);
}

TEST(StorageLoadCoordinates, ALoadOfAnotherLengthIsConvertedToTheTexturesCoordinates) {
    EXPECT_EQ(texelWritesLowered("RWTexture2D<float4> H;\nfloat4 f(int2 c) { return H.Load(int3(c, 0)); }"),
              "RWTexture2D<float4> H;\nfloat4 f(int2 c) { return H.Load(( int2 ) ( int3(c, 0))); }");
    // A sampled texture's Load, and a Load with a status, stay.
    for (const std::string text : {"Texture2D<float4> T;\nfloat4 f(int2 c) { return T.Load(int3(c, 0)); }",
                                   "RWTexture2D<float4> H;\nfloat4 f(int2 c, out uint s) { return H.Load(c, s); }"})
        EXPECT_EQ(texelWritesLowered(text), text);
}

} // namespace
} // namespace iblkit::lowering
