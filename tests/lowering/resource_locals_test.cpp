// A local that holds a resource is its value at each use, unless what the value reads changes.
#include "lowering.hpp"

#include <gtest/gtest.h>

namespace iblkit::lowering {
namespace {

std::string inlined(const std::string& text) { return lowerHlsl(text, "a.hlsl", HlslVersion::Hlsl2021).text; }

TEST(ResourceLocals, EachUseNamesTheResourceTheLocalWasGiven) {
    EXPECT_EQ(inlined("float f(uint i) { ByteAddressBuffer b = Buffers[i + 1]; return asfloat(b.Load(0)) + b.Load(4); }"),
              "float f(uint i) { return asfloat(Buffers [ i + 1 ].Load(0)) + Buffers [ i + 1 ].Load(4); }");
    EXPECT_EQ(inlined("void f() { const StructuredBuffer<float> w = W; { x = w[0]; } }"), "void f() { { x = W[0]; } }");
    // A value that is not a name and its indices keeps its own parentheses.
    EXPECT_EQ(inlined("void f(bool c) { Texture2D t = c ? A : B; x = t.Load(0); }"), "void f(bool c) { x = (c ? A : B).Load(0); }");
}

TEST(ResourceLocals, AValueWhoseOperandsChangeLaterIsLeftToGlslang) {
    for (const std::string text : {"void f(uint i) { ByteAddressBuffer b = Buffers[i]; i = 2; x = b.Load(0); }",
                                   "void f(uint i) { ByteAddressBuffer b = Buffers[i]; i++; x = b.Load(0); }",
                                   "void f(S s) { ByteAddressBuffer b = Buffers[s.index]; s.index = 1; x = b.Load(0); }"})
        EXPECT_EQ(inlined(text), text);
}

TEST(ResourceLocals, WritesToOtherMembersOfAStructItReadsDoNotStopIt) {
    EXPECT_EQ(inlined("void f(G g) { ByteAddressBuffer b = Buffers[g.geometry.index]; g.positions[0] = 1; g.count += 2; x = b.Load(0); }"),
              "void f(G g) { g.positions[0] = 1; g.count += 2; x = Buffers [ g . geometry . index ].Load(0); }");
    // Writing the member read, or the struct that holds it, does.
    for (const std::string text : {"void f(G g) { ByteAddressBuffer b = Buffers[g.geometry.index]; g.geometry = h; x = b.Load(0); }",
                                   "void f(G g) { ByteAddressBuffer b = Buffers[g.geometry.index]; g = h; x = b.Load(0); }",
                                   "void f(G g) { ByteAddressBuffer b = Buffers[g.geometry.index]; g.geometry.index++; x = b.Load(0); }"})
        EXPECT_EQ(inlined(text), text);
}

TEST(ResourceLocals, AValueGlslangCannotReadStaysForItsRefusal) {
    // Without this, an unused local's ResourceDescriptorHeap would vanish instead of being named.
    EXPECT_THROW(inlined("void f() { RWBuffer<float> b = ResourceDescriptorHeap[0]; }"), std::exception);
}

TEST(ResourceLocals, GlobalResourcesAndOtherLocalsStay) {
    const std::string text = "ByteAddressBuffer B : register(t0);\nvoid f() { float4 c = T.Load(0); uint n = B.Load(0); }";
    EXPECT_EQ(inlined(text), text);
}

} // namespace
} // namespace iblkit::lowering
