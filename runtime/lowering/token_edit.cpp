#include "token_edit.hpp"

#include "lowering_error.hpp"

#include <algorithm>
#include <set>

namespace iblkit::lowering {
namespace {

std::string newlinesOf(std::string_view text) { return std::string(std::count(text.begin(), text.end(), '\n'), '\n'); }

} // namespace

bool opensBracket(const Token& token) { return token.is("(") || token.is("[") || token.is("{"); }
bool closesBracket(const Token& token) { return token.is(")") || token.is("]") || token.is("}"); }

std::string spacedText(TokenSpan tokens) {
    std::string text;
    for (const auto& token : tokens) text += (text.empty() ? "" : " ") + token.text;
    return text;
}

size_t matchingClose(TokenSpan tokens, size_t open) {
    int depth = 0;
    for (size_t i = open; i < tokens.size(); ++i) {
        if (opensBracket(tokens[i])) ++depth;
        if (closesBracket(tokens[i]) && --depth == 0) return i;
    }
    refuse(tokens[open], "'" + tokens[open].text + "' is never closed");
}

std::vector<std::pair<size_t, size_t>> splitAtCommas(TokenSpan tokens, size_t begin, size_t end) {
    std::vector<std::pair<size_t, size_t>> parts;
    size_t start = begin;
    for (size_t i = begin; i < end; ++i) {
        if (opensBracket(tokens[i])) i = matchingClose(tokens, i);
        else if (tokens[i].is(",")) {
            parts.emplace_back(start, i);
            start = i + 1;
        }
    }
    parts.emplace_back(start, end);
    return parts;
}

void TokenWriter::keep(const Token& token) {
    tokens_.push_back(token);
    tokens_.back().leading = pendingNewlines_ + token.leading;
    pendingNewlines_.clear();
}

void TokenWriter::keep(TokenSpan tokens) {
    for (const auto& token : tokens) keep(token);
}

void TokenWriter::keepTight(const Token& token) {
    Token tight = token;
    tight.leading = newlinesOf(token.leading);
    keep(tight);
}

void TokenWriter::drop(const Token& token) { pendingNewlines_ += newlinesOf(token.leading) + newlinesOf(token.text); }

void TokenWriter::drop(TokenSpan tokens) {
    for (const auto& token : tokens) drop(token);
}

void TokenWriter::add(std::string_view text, const SourcePlace& place, std::string_view leading) {
    auto made = tokenize(text, place.file);
    made.pop_back(); // the End token
    for (size_t i = 0; i < made.size(); ++i) {
        made[i].place = place;
        if (i == 0) made[i].leading = leading;
        keep(made[i]);
    }
}

std::vector<Token> TokenWriter::finish() { return std::move(tokens_); }

bool followsMemberAccess(TokenSpan tokens, size_t i) { return i > 0 && (tokens[i - 1].is(".") || tokens[i - 1].is("->")); }

bool followsQualifier(TokenSpan tokens, size_t i) { return i > 0 && tokens[i - 1].is("::"); }

bool isTypeLike(const Token& token) {
    static const std::set<std::string, std::less<>> statementWords{
        "return", "else", "case", "do", "goto", "in", "out", "inout",
        "if", "while", "for", "switch", "break", "continue", "discard"};
    return (token.isIdentifier() && !statementWords.contains(token.text)) || token.is(">") || token.is("]");
}

void refuse(const Token& at, const std::string& what) {
    throw LoweringError(at.place.describe() + ": error: " + what);
}

} // namespace iblkit::lowering
