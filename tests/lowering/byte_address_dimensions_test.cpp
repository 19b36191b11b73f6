// A byte-address buffer's GetDimensions is made bytes, as Direct3D answers; glslang answers words.
#include "lowering.hpp"

#include <gtest/gtest.h>

namespace iblkit::lowering {
namespace {

std::string dimensionsLowered(const std::string& text) { return lowerHlsl(text, "a.hlsl", HlslVersion::Hlsl2021).text; }

TEST(ByteAddressDimensions, TheCallBecomesABlockThatScalesItsResult) {
    EXPECT_EQ(dimensionsLowered("ByteAddressBuffer B;\nvoid f() { uint n; B.GetDimensions(n); }"),
              "ByteAddressBuffer B;\nvoid f() { uint n; { B.GetDimensions(n); n *= 4u; } }");
    const auto text = dimensionsLowered("void f(RWByteAddressBuffer p, out uint s[2]) { if (true) p.GetDimensions(s[1]); }");
    EXPECT_NE(text.find("if (true) { p.GetDimensions(s[1]); s [ 1 ] *= 4u; }"), std::string::npos) << text;
}

TEST(ByteAddressDimensions, LeavesStructuredBuffersTexturesAndMembers) {
    for (const std::string text : {"StructuredBuffer<uint> B;\nvoid f() { uint n, s; B.GetDimensions(n, s); }",
                                   "Texture2D T;\nvoid f() { uint w, h; T.GetDimensions(w, h); }",
                                   "struct S { uint GetDimensions; };\nByteAddressBuffer B;\nvoid f(S s) { uint n = s.GetDimensions; }"})
        EXPECT_EQ(dimensionsLowered(text), text);
}

} // namespace
} // namespace iblkit::lowering
