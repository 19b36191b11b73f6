#include "non_uniform_index.hpp"

#include "token_edit.hpp"

namespace iblkit::lowering {
namespace {

constexpr const char* kIntrinsic = "NonUniformResourceIndex";

bool definesItsOwn(const std::vector<Token>& tokens) {
    for (size_t i = 1; i + 1 < tokens.size(); ++i)
        if (tokens[i].is(kIntrinsic) && tokens[i + 1].is("(") && isTypeLike(tokens[i - 1])) return true;
    return false;
}

} // namespace

std::vector<Token> lowerNonUniformResourceIndex(const std::vector<Token>& tokens) {
    if (definesItsOwn(tokens)) return tokens;
    TokenWriter writer;
    for (size_t i = 0; i < tokens.size(); ++i) {
        const bool call = tokens[i].is(kIntrinsic) && i + 1 < tokens.size() && tokens[i + 1].is("(") &&
                          !followsMemberAccess(tokens, i) && !followsQualifier(tokens, i);
        if (call) writer.drop(tokens[i]);
        else writer.keep(tokens[i]);
    }
    return writer.finish();
}

} // namespace iblkit::lowering
