// Templates become one function or struct per argument list; sizeof becomes the size.
#include "lowering.hpp"
#include "lowering_error_of.hpp"

#include <gtest/gtest.h>

namespace iblkit::lowering {
namespace {

std::string instantiated(const std::string& text) { return lowerHlsl(text, "a.hlsl", HlslVersion::Hlsl2021).text; }

TEST(Templates, AFunctionIsInstantiatedOncePerArgumentListBeforeItsFirstUse) {
    EXPECT_EQ(instantiated("template <typename T> T twice(T x) { return x * 2; }\n"
                           "float f(float a, int2 b) { return twice(a) + twice(b).x + twice<float>(3); }"),
              " float twice__float ( float x ) { return x * 2 ; } int2 twice__int2 ( int2 x ) { return x * 2 ; }\n"
              "float f(float a, int2 b) { return twice__float(a) + twice__int2(b).x + twice__float(3); }");
}

TEST(Templates, StructsConstantsAndTemplatesUsingTemplates) {
    const auto text = instantiated("template <typename T, uint N> struct Ring { T items[N]; };\n"
                                   "template <typename T> T first(Ring<T, 4> r) { return r.items[0]; }\n"
                                   "float f() { Ring<float, 4> r; return first(r); }");
    EXPECT_NE(text.find("struct Ring__float__4 { float items [ 4 ] ; } ;"), std::string::npos) << text;
    EXPECT_NE(text.find("float first__float ( Ring__float__4 r )"), std::string::npos) << text;
    EXPECT_NE(text.find("Ring__float__4 r; return first__float(r);"), std::string::npos) << text;
}

TEST(Templates, SizeofIsTheStructuredBufferSize) {
    EXPECT_EQ(instantiated("struct S { float3 a; float b; uint2 c; double d; };\nuint n = sizeof(S) + sizeof(float4x4);"),
              "struct S { float3 a; float b; uint2 c; double d; };\nuint n = 32u + 64u;");
    EXPECT_EQ(instantiated("uint f() { half2 h; return sizeof(h); }"), "uint f() { half2 h; return 8u; }");
}

TEST(Templates, WhatCannotBeInstantiatedIsRefusedByName) {
    EXPECT_EQ(errorOf("template <typename T> T id(T x) { return x; }\nfloat f(float a) { return id(a * 2); }"),
              "a.hlsl:2:27: error: the template arguments of 'id' cannot be deduced by the kit from this call (it deduces "
              "them from variables, literals, constructors and casts): write them, as in id<float>(...)");
    EXPECT_EQ(errorOf("uint f() { return sizeof(g()); }"),
              "a.hlsl:1:19: error: sizeof of what the kit cannot lay out here: it takes a scalar, vector, matrix or struct "
              "type, or a variable of one; write the size");
}

} // namespace
} // namespace iblkit::lowering
