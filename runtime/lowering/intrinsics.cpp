#include "intrinsics.hpp"

#include "token_edit.hpp"

#include <array>
#include <set>
#include <string>

namespace iblkit::lowering {
namespace {

struct Intrinsic {
    std::string_view name;
    size_t arguments;
    std::array<std::string_view, 3> joints; // what stands between the parenthesized arguments
};

constexpr std::array kIntrinsics{Intrinsic{"select", 3, {"?", ":", ""}}, Intrinsic{"and", 2, {"&&", "", ""}},
                                 Intrinsic{"or", 2, {"||", "", ""}}};

const Intrinsic* intrinsicNamed(const std::string& name) {
    for (const auto& intrinsic : kIntrinsics)
        if (intrinsic.name == name) return &intrinsic;
    return nullptr;
}

// "float select(" or "bool2 and(": a type before the name makes it the shader's own function.
std::set<std::string> functionsTheShaderDefines(TokenSpan tokens) {
    std::set<std::string> defined;
    for (size_t i = 1; i + 1 < tokens.size(); ++i) {
        if (tokens[i].isIdentifier() && intrinsicNamed(tokens[i].text) && isTypeLike(tokens[i - 1]) && tokens[i + 1].is("("))
            defined.insert(tokens[i].text);
    }
    return defined;
}

class IntrinsicLowering {
public:
    explicit IntrinsicLowering(TokenSpan tokens) : tokens_(tokens), ownFunctions_(functionsTheShaderDefines(tokens)) {}

    std::vector<Token> run() {
        lower(0, tokens_.size());
        return writer_.finish();
    }

private:
    bool isCall(size_t i) const {
        if (!tokens_[i].isIdentifier() || !intrinsicNamed(tokens_[i].text) || ownFunctions_.contains(tokens_[i].text)) return false;
        const bool member = followsMemberAccess(tokens_, i) || followsQualifier(tokens_, i);
        return !member && i + 1 < tokens_.size() && tokens_[i + 1].is("(");
    }

    // The first token of a parenthesized argument loses its spaces: "(a)", not "( a)".
    void lower(size_t begin, size_t end, bool tight = false) {
        for (size_t i = begin; i < end; ++i) {
            if (!isCall(i)) {
                if (tight && i == begin) writer_.keepTight(tokens_[i]);
                else writer_.keep(tokens_[i]);
                continue;
            }
            i = lowerCall(i, tight && i == begin);
        }
    }

    // Returns the index of the call's closing parenthesis.
    size_t lowerCall(size_t at, bool tight) {
        const Intrinsic& intrinsic = *intrinsicNamed(tokens_[at].text);
        const size_t close = matchingClose(tokens_, at + 1);
        const auto arguments = splitAtCommas(tokens_, at + 2, close);
        if (arguments.size() != intrinsic.arguments || arguments.front().first == arguments.front().second)
            refuse(tokens_[at], std::string(intrinsic.name) + " takes " + std::to_string(intrinsic.arguments) +
                                    " arguments, not " + std::to_string(close == at + 2 ? 0 : arguments.size()));
        const SourcePlace& place = tokens_[at].place;
        if (tight) writer_.add("(", place, "");
        else writer_.replace(tokens_[at], "(");
        for (size_t n = 0; n < arguments.size(); ++n) {
            writer_.drop(tokens_[arguments[n].first - 1]); // "select(" or a comma
            writer_.add("(", place, n == 0 ? "" : " ");
            lower(arguments[n].first, arguments[n].second, true);
            writer_.add(")", place, "");
            if (!intrinsic.joints[n].empty()) writer_.add(intrinsic.joints[n], place);
        }
        writer_.drop(tokens_[close]);
        writer_.add(")", place, "");
        return close;
    }

    TokenSpan tokens_;
    std::set<std::string> ownFunctions_;
    TokenWriter writer_;
};

} // namespace

std::vector<Token> lowerIntrinsics(const std::vector<Token>& tokens) { return IntrinsicLowering(tokens).run(); }

} // namespace iblkit::lowering
