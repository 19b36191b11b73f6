// A struct's static members, enums and static member functions move to a namespace of its name.
#include "lowering.hpp"

#include <gtest/gtest.h>

namespace iblkit::lowering {
namespace {

std::string hoisted(const std::string& text) { return lowerHlsl(text, "a.hlsl", HlslVersion::Hlsl2021).text; }

TEST(StructScope, StaticMembersBecomeNamespacedConstantsAndTheirValuesInsideTheStruct) {
    const auto text = hoisted("struct S { static const int N = 2 * 2; float a[N]; };\nint f() { return S::N; }\n");
    EXPECT_NE(text.find("static const int S__N = 2 * 2;"), std::string::npos) << text;
    EXPECT_NE(text.find("float a[(2 * 2)];"), std::string::npos) << text;
    EXPECT_NE(text.find("return S__N;"), std::string::npos) << text;
}

TEST(StructScope, EnumsAndStaticFunctionsMoveOutWithTheirNames) {
    const auto text = hoisted("struct L { enum Kind { Point, Spot }; Kind kind; static L Make() { L l; return l; } };\n"
                              "int f() { L l = L::Make(); return L::Spot; }\n");
    EXPECT_EQ(text.find("enum"), std::string::npos) << text; // lowered to constants
    EXPECT_NE(text.find("L__Kind kind;"), std::string::npos) << text;
    EXPECT_NE(text.find("L__Make()"), std::string::npos) << text;
    // The function comes after the struct whose type it returns.
    EXPECT_LT(text.find("struct L"), text.find("L L__Make")) << text;
}

TEST(StructScope, MemberFunctionsAndPlainMembersStay) {
    const std::string text = "struct S { float x; float Twice() { return 2 * x; } static const float k; };";
    EXPECT_EQ(hoisted(text), text);
}

} // namespace
} // namespace iblkit::lowering
