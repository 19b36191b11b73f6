#include "type_spellings.hpp"

#include "token_edit.hpp"

#include <set>
#include <string>

namespace iblkit::lowering {
namespace {

bool isScalarType(const Token& token) {
    static const std::set<std::string, std::less<>> kScalars{
        "bool", "int", "uint", "dword", "float", "double", "half", "min16float", "min10float", "min16int", "min12int",
        "min16uint", "int64_t", "uint64_t", "float16_t", "int16_t", "uint16_t", "float32_t", "int32_t", "uint32_t", "float64_t"};
    return token.isIdentifier() && kScalars.contains(token.text);
}

bool isDimension(const Token& token) {
    return token.kind == TokenKind::Number && token.text.size() == 1 && token.text[0] >= '1' && token.text[0] <= '4';
}

// "vector < T , N >" or "matrix < T , R , C >" at i: the tokens it spans, or 0.
size_t templateLength(const std::vector<Token>& tokens, size_t i) {
    const auto at = [&](size_t k) -> const Token& { return tokens[std::min(i + k, tokens.size() - 1)]; };
    if (!at(1).is("<") || !isScalarType(at(2)) || !at(3).is(",") || !isDimension(at(4))) return 0;
    if (tokens[i].is("vector") && at(5).is(">")) return 6;
    if (tokens[i].is("matrix") && at(5).is(",") && isDimension(at(6)) && at(7).is(">")) return 8;
    return 0;
}

} // namespace

std::vector<Token> lowerTypeSpellings(const std::vector<Token>& tokens) {
    TokenWriter writer;
    for (size_t i = 0; i < tokens.size(); ++i) {
        const Token& token = tokens[i];
        const bool member = followsMemberAccess(tokens, i) || followsQualifier(tokens, i);
        if (!member && (token.is("vector") || token.is("matrix"))) {
            if (const size_t length = templateLength(tokens, i)) {
                std::string spelled = tokens[i + 2].text + tokens[i + 4].text;
                if (length == 8) spelled += "x" + tokens[i + 6].text;
                writer.replace(token, spelled);
                for (size_t k = 1; k < length; ++k) writer.drop(tokens[i + k]);
                i += length - 1;
                continue;
            }
        }
        if (!member && token.is("unsigned")) {
            const bool withInt = i + 1 < tokens.size() && tokens[i + 1].is("int");
            writer.replace(token, "uint");
            if (withInt) writer.drop(tokens[++i]);
            continue;
        }
        writer.keep(token);
    }
    return writer.finish();
}

} // namespace iblkit::lowering
