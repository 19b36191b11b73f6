#include "refusals.hpp"

#include "token_edit.hpp"

namespace iblkit::lowering {

void refuseUnlowerable(const std::vector<Token>& tokens) {
    std::vector<bool> braces; // for each open brace: whether it opens a struct
    bool nextBraceIsStruct = false;
    for (size_t i = 0; i + 1 < tokens.size(); ++i) {
        const Token& token = tokens[i];
        const Token& next = tokens[i + 1];
        const bool member = followsMemberAccess(tokens, i) || followsQualifier(tokens, i);
        if (member || !(token.isIdentifier() || token.kind == TokenKind::Punctuator)) continue;
        if (token.is("operator") && (next.kind == TokenKind::Punctuator || next.is("[")))
            refuse(token, "operator overloading ('operator" + next.text + "') cannot be lowered: write a named function");
        if (token.is("struct") || token.is("class")) nextBraceIsStruct = true;
        if (token.is(";")) nextBraceIsStruct = false;
        if (token.is("{")) {
            braces.push_back(nextBraceIsStruct);
            nextBraceIsStruct = false;
        }
        if (token.is("}") && !braces.empty()) braces.pop_back();
        const bool inStruct = !braces.empty() && braces.back();
        if (inStruct && token.is("enum")) refuse(token, "an enum inside a struct cannot be lowered: declare it outside");
        if (inStruct && token.isIdentifier() && next.is(":") && i + 3 < tokens.size() && tokens[i + 2].kind == TokenKind::Number &&
            (tokens[i + 3].is(";") || tokens[i + 3].is(",")))
            refuse(token, "the bitfield '" + token.text + " : " + tokens[i + 2].text +
                              "' cannot be lowered: use a whole member and shift and mask it");
    }
}

} // namespace iblkit::lowering
