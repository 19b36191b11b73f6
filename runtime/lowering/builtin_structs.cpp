#include "builtin_structs.hpp"

#include "token_edit.hpp"

#include <algorithm>
#include <array>
#include <string_view>
#include <utility>

namespace iblkit::lowering {
namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 2> kBuiltinStructs{{
    {"RayDesc", "struct RayDesc { float3 Origin ; float TMin ; float3 Direction ; float TMax ; } ;"},
    {"BuiltInTriangleIntersectionAttributes", "struct BuiltInTriangleIntersectionAttributes { float2 barycentrics ; } ;"},
}};

bool uses(const std::vector<Token>& tokens, std::string_view name) {
    return std::any_of(tokens.begin(), tokens.end(), [&](const Token& token) { return token.isIdentifier() && token.text == name; });
}

bool declares(const std::vector<Token>& tokens, std::string_view name) {
    for (size_t i = 1; i < tokens.size(); ++i)
        if (tokens[i].isIdentifier() && tokens[i].text == name && (tokens[i - 1].is("struct") || tokens[i - 1].is("typedef")))
            return true;
    return false;
}

} // namespace

std::vector<Token> declareBuiltinStructs(const std::vector<Token>& tokens) {
    std::string declarations;
    for (const auto& [name, declaration] : kBuiltinStructs)
        if (uses(tokens, name) && !declares(tokens, name)) declarations += std::string(declaration) + " ";
    if (declarations.empty()) return tokens;
    // On the line of the first token that is not a directive, before it: every line keeps its number.
    size_t first = 0;
    while (first + 1 < tokens.size() && tokens[first].kind == TokenKind::Directive) ++first;
    TokenWriter writer;
    writer.keep(TokenSpan(tokens).subspan(0, first));
    writer.add(declarations, tokens[first].place, tokens[first].leading);
    Token spaced = tokens[first];
    spaced.leading = " ";
    writer.keep(spaced);
    writer.keep(TokenSpan(tokens).subspan(first + 1));
    return writer.finish();
}

} // namespace iblkit::lowering
