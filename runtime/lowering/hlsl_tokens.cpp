#include "hlsl_tokens.hpp"

#include "lowering_error.hpp"

#include <array>
#include <cctype>
#include <charconv>

namespace iblkit::lowering {
namespace {

// Longest first, so that "<<=" is not read as "<<" and "=".
constexpr std::array<std::string_view, 22> kLongPunctuators{
    "<<=", ">>=", "::", "->", "++", "--", "<<", ">>", "<=", ">=", "==",
    "!=",  "&&",  "||", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^="};
constexpr std::string_view kShortPunctuators = "{}[]();,.:?~!+-*/%<>=&|^";

bool isIdentifierStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentifierPart(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

class Tokenizer {
public:
    Tokenizer(std::string_view text, const std::string& sourceName) : text_(text) { place_.file = sourceName; }

    std::vector<Token> run() {
        std::vector<Token> tokens;
        for (;;) {
            Token token;
            token.leading = whiteSpace();
            token.place = place_;
            if (at_ == text_.size()) {
                tokens.push_back(std::move(token));
                return tokens;
            }
            readToken(token);
            tokens.push_back(std::move(token));
        }
    }

private:
    std::string whiteSpace() {
        const size_t start = at_;
        while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) advance();
        return std::string(text_.substr(start, at_ - start));
    }

    void advance() {
        if (text_[at_] == '\n') {
            ++place_.line;
            place_.column = 1;
            lineStart_ = true;
        } else {
            ++place_.column;
            if (!std::isspace(static_cast<unsigned char>(text_[at_]))) lineStart_ = false;
        }
        ++at_;
    }

    std::string take(size_t length) {
        std::string taken(text_.substr(at_, length));
        for (size_t i = 0; i < length; ++i) advance();
        return taken;
    }

    void readToken(Token& token) {
        const char c = text_[at_];
        if (c == '#' && lineStart_) return readDirective(token);
        if (isIdentifierStart(c)) return read(token, TokenKind::Identifier, lengthWhile(isIdentifierPart));
        if (isDigit(c) || (c == '.' && at_ + 1 < text_.size() && isDigit(text_[at_ + 1])))
            return read(token, TokenKind::Number, numberLength());
        if (c == '"') return read(token, TokenKind::String, stringLength(token.place));
        for (const auto punctuator : kLongPunctuators)
            if (text_.substr(at_, punctuator.size()) == punctuator) return read(token, TokenKind::Punctuator, punctuator.size());
        if (kShortPunctuators.find(c) != std::string_view::npos) return read(token, TokenKind::Punctuator, 1);
        throw LoweringError(token.place.describe() + ": error: unexpected character '" + std::string(1, c) + "'");
    }

    void read(Token& token, TokenKind kind, size_t length) {
        token.kind = kind;
        token.text = take(length);
    }

    template <typename Predicate>
    size_t lengthWhile(Predicate predicate) const {
        size_t end = at_;
        while (end < text_.size() && predicate(text_[end])) ++end;
        return end - at_;
    }

    // A preprocessing number: digits, letters, '_', '.', and a sign after an exponent letter.
    size_t numberLength() const {
        size_t end = at_;
        while (end < text_.size()) {
            const char c = text_[end];
            const bool sign = (c == '+' || c == '-') && end > at_ &&
                              std::string_view("eEpP").find(text_[end - 1]) != std::string_view::npos &&
                              !(text_[at_] == '0' && end > at_ + 1 && (text_[at_ + 1] == 'x' || text_[at_ + 1] == 'X'));
            if (!isIdentifierPart(c) && c != '.' && !sign) break;
            ++end;
        }
        return end - at_;
    }

    size_t stringLength(const SourcePlace& place) const {
        for (size_t end = at_ + 1; end < text_.size() && text_[end] != '\n'; ++end) {
            if (text_[end] == '\\') ++end;
            else if (text_[end] == '"') return end + 1 - at_;
        }
        throw LoweringError(place.describe() + ": error: a string that does not end on its line");
    }

    // "#line N" or "#line N "file"" sets the place of the next line; any other directive
    // (#pragma, #extension) passes through.
    void readDirective(Token& token) {
        token.kind = TokenKind::Directive;
        token.text = take(lengthWhile([](char c) { return c != '\n'; }));
        constexpr std::string_view kLine = "#line ";
        if (token.text.rfind(kLine, 0) != 0) return;
        const std::string_view rest = std::string_view(token.text).substr(kLine.size());
        int number = 0;
        const auto [end, error] = std::from_chars(rest.data(), rest.data() + rest.size(), number);
        if (error != std::errc()) return;
        const std::string_view afterNumber(end, rest.data() + rest.size());
        const auto open = afterNumber.find('"'), close = afterNumber.rfind('"');
        if (open != std::string_view::npos && close > open) place_.file = std::string(afterNumber.substr(open + 1, close - open - 1));
        // The directive takes its own newline, so that the line after it is `number`.
        if (at_ < text_.size()) token.text += take(1);
        place_.line = number;
    }

    std::string_view text_;
    size_t at_ = 0;
    SourcePlace place_;
    bool lineStart_ = true;
};

} // namespace

std::vector<Token> tokenize(std::string_view text, const std::string& sourceName) {
    return Tokenizer(text, sourceName).run();
}

std::string render(const std::vector<Token>& tokens) {
    std::string text;
    for (const auto& token : tokens) text += token.leading + token.text;
    return text;
}

} // namespace iblkit::lowering
