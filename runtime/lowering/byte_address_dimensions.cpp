#include "byte_address_dimensions.hpp"

#include "token_edit.hpp"

#include <set>

namespace iblkit::lowering {
namespace {

bool isByteAddressType(const Token& token) {
    return token.is("ByteAddressBuffer") || token.is("RWByteAddressBuffer") || token.is("RasterizerOrderedByteAddressBuffer");
}

// name . GetDimensions ( argument ) ; at tokens[i]: the index of the ';', or 0.
size_t getDimensionsStatement(const std::vector<Token>& tokens, size_t i) {
    if (i + 4 >= tokens.size() || !tokens[i + 1].is(".") || !tokens[i + 2].is("GetDimensions") || !tokens[i + 3].is("(")) return 0;
    const size_t close = matchingClose(tokens, i + 3);
    if (close + 1 >= tokens.size() || !tokens[close + 1].is(";") || close == i + 4) return 0;
    if (splitAtCommas(tokens, i + 4, close).size() != 1) return 0;
    return close + 1;
}

std::string textOf(const std::vector<Token>& tokens, size_t begin, size_t end) {
    std::string text;
    for (size_t i = begin; i < end; ++i) text += (i == begin ? "" : " ") + tokens[i].text;
    return text;
}

} // namespace

std::vector<Token> scaleByteAddressDimensions(const std::vector<Token>& tokens) {
    std::set<std::string> declared;
    TokenWriter writer;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (isByteAddressType(tokens[i]) && i + 1 < tokens.size() && tokens[i + 1].isIdentifier()) declared.insert(tokens[i + 1].text);
        const bool use = tokens[i].isIdentifier() && declared.contains(tokens[i].text) && !followsMemberAccess(tokens, i) &&
                         (i == 0 || !isByteAddressType(tokens[i - 1]));
        const size_t end = use ? getDimensionsStatement(tokens, i) : 0;
        if (!end) {
            writer.keep(tokens[i]);
            continue;
        }
        writer.add("{", tokens[i].place, tokens[i].leading);
        Token first = tokens[i];
        first.leading = " ";
        writer.keep(first);
        writer.keep(TokenSpan(tokens).subspan(i + 1, end - i));
        writer.add(textOf(tokens, i + 4, end - 1) + " *= 4u; }", tokens[end].place);
        i = end;
    }
    return writer.finish();
}

} // namespace iblkit::lowering
