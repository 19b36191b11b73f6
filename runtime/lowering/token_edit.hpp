#pragma once

#include "hlsl_tokens.hpp"

#include <span>
#include <string_view>
#include <vector>

namespace iblkit::lowering {

using TokenSpan = std::span<const Token>;

// "(", "[" or "{"; ")", "]" or "}".
bool opensBracket(const Token& token);
bool closesBracket(const Token& token);

// The tokens' texts joined by single spaces: an expression to write again elsewhere.
std::string spacedText(TokenSpan tokens);

// The index of the bracket that closes the one at `open` ("(", "[" or "{"), or throws
// LoweringError naming where the open one stands.
size_t matchingClose(TokenSpan tokens, size_t open);

// The ranges [begin, end) between the commas at bracket depth 0 of tokens[begin, end).
std::vector<std::pair<size_t, size_t>> splitAtCommas(TokenSpan tokens, size_t begin, size_t end);

// Builds a token list for a lowering: tokens kept, dropped or made anew. A dropped token's
// newlines move to the next written token, so every later line keeps its number.
class TokenWriter {
public:
    void keep(const Token& token);
    void keep(TokenSpan tokens);
    void drop(const Token& token);
    void drop(TokenSpan tokens);
    // New tokens, made from `text`, that stand at `place`; the first has `leading` white space
    // after the newlines of the tokens dropped before it.
    void add(std::string_view text, const SourcePlace& place, std::string_view leading = " ");
    // New tokens from `text` in the place of `old`, with its white space.
    void replace(const Token& old, std::string_view text) { add(text, old.place, old.leading); }
    // Keeps the token without the spaces before it (its newlines stay).
    void keepTight(const Token& token);
    std::vector<Token> finish();

private:
    std::vector<Token> tokens_;
    std::string pendingNewlines_;
};

// Whether tokens[i] follows "." or "->": a member's name, not a name of its own scope.
bool followsMemberAccess(TokenSpan tokens, size_t i);
// Whether tokens[i] follows "::": a qualified name's later part.
bool followsQualifier(TokenSpan tokens, size_t i);
// A token that can stand right before a declared name: an identifier other than a statement
// word (return, else, case, ...), or the end of a type (">" of a template, "]" of an array).
bool isTypeLike(const Token& token);

// For messages: "file:line:col: error: <what>".
[[noreturn]] void refuse(const Token& at, const std::string& what);

} // namespace iblkit::lowering
