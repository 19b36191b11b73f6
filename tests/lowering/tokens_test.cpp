// The tokenizer the lowering works on: it gives the text back byte for byte, and every token
// knows the file and line the #line directives give it.
#include "hlsl_tokens.hpp"
#include "lowering_error.hpp"

#include <gtest/gtest.h>

namespace iblkit::lowering {
namespace {

TEST(Tokens, RenderGivesTheTextBack) {
    const std::string text = "#line 1 \"a.hlsli\"\nfloat f(float x){ return x >>= 2 ? 1.5e-3f : 0x1Fu; }\n"
                             "#pragma pack_matrix(row_major)\n[[vk :: binding(5, 1)]] RWTexture2D < float4 > t;\n  ";
    EXPECT_EQ(render(tokenize(text, "main.hlsl")), text);
}

TEST(Tokens, KindsAndLongestPunctuators) {
    const auto tokens = tokenize("a<<=1.5e+3f::\"s\"", "x.hlsl");
    ASSERT_EQ(tokens.size(), 6u);
    EXPECT_EQ(tokens[0].kind, TokenKind::Identifier);
    EXPECT_EQ(tokens[1].text, "<<=");
    EXPECT_EQ(tokens[2].text, "1.5e+3f");
    EXPECT_EQ(tokens[2].kind, TokenKind::Number);
    EXPECT_EQ(tokens[3].text, "::");
    EXPECT_EQ(tokens[4].kind, TokenKind::String);
    EXPECT_EQ(tokens[5].kind, TokenKind::End);
}

TEST(Tokens, LineDirectivesGiveThePlaces) {
    const auto tokens = tokenize("a\n#line 10 \"h.hlsli\"\nb\n\nc\n#line 3\nd", "main.hlsl");
    ASSERT_EQ(tokens.size(), 7u);
    EXPECT_EQ(tokens[0].place.describe(), "main.hlsl:1:1");
    EXPECT_EQ(tokens[2].place.describe(), "h.hlsli:10:1");
    EXPECT_EQ(tokens[3].place.describe(), "h.hlsli:12:1");
    EXPECT_EQ(tokens[5].place.describe(), "h.hlsli:3:1");
}

TEST(Tokens, AHexNumberWithESignIsTwoTokens) {
    const auto tokens = tokenize("0x1e+1", "x.hlsl");
    EXPECT_EQ(tokens[0].text, "0x1e");
    EXPECT_EQ(tokens[1].text, "+");
}

TEST(Tokens, AStrayCharacterIsAnErrorWithItsPlace) {
    try {
        tokenize("float a;\n  $b;", "x.hlsl");
        FAIL() << "no error";
    } catch (const LoweringError& error) {
        EXPECT_STREQ(error.what(), "x.hlsl:2:3: error: unexpected character '$'");
    }
}

} // namespace
} // namespace iblkit::lowering
