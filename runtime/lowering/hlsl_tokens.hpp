#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace iblkit::lowering {

// Where a token stands in the user's files: the preprocessed text carries glslang's
// `#line N "file"` directives, so the place is the original file's, not the text's.
struct SourcePlace {
    std::string file;
    int line = 1;
    int column = 1; // in the preprocessed text (glslang's preprocessor respaces a line)

    std::string describe() const { return file + ":" + std::to_string(line) + ":" + std::to_string(column); }
};

enum class TokenKind { Identifier, Number, String, Punctuator, Directive, End };

// One token of preprocessed HLSL, with the white space before it, so that joining the tokens
// gives the text back byte for byte. A directive (#line, #pragma, #extension) is one token.
struct Token {
    TokenKind kind = TokenKind::End;
    std::string text;
    std::string leading; // spaces and newlines before the token
    SourcePlace place;

    bool is(std::string_view spelling) const { return kind != TokenKind::String && text == spelling; }
    bool isIdentifier() const { return kind == TokenKind::Identifier; }
};

// Splits preprocessed HLSL (no comments, no macros) into tokens ending in one End token that
// holds the trailing white space. Throws LoweringError on a character HLSL has no token for.
std::vector<Token> tokenize(std::string_view text, const std::string& sourceName);

// The text of the tokens, white space included.
std::string render(const std::vector<Token>& tokens);

} // namespace iblkit::lowering
