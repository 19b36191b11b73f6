#include "struct_conversions.hpp"

#include "token_edit.hpp"

#include <map>
#include <optional>
#include <string>

namespace iblkit::lowering {
namespace {

struct Member {
    std::string type, name;
};

// Each struct's data members, in order: "Type name [: SEMANTIC];" at the struct's own depth.
std::map<std::string, std::vector<Member>> structMembers(const std::vector<Token>& tokens) {
    std::map<std::string, std::vector<Member>> structs;
    for (size_t i = 0; i + 2 < tokens.size(); ++i) {
        if (!tokens[i].is("struct") || !tokens[i + 1].isIdentifier() || !tokens[i + 2].is("{")) continue;
        const size_t close = matchingClose(tokens, i + 2);
        std::vector<Member> members;
        bool plain = true;
        for (size_t k = i + 3; k < close; ++k) {
            if (opensBracket(tokens[k]) && !tokens[k].is("[")) plain = false; // a member function
            const bool declared = tokens[k].isIdentifier() && tokens[k + 1].isIdentifier() &&
                                  (tokens[k + 2].is(";") || tokens[k + 2].is(":"));
            if (declared && (tokens[k - 1].is(";") || tokens[k - 1].is("{"))) members.push_back({tokens[k].text, tokens[k + 1].text});
        }
        if (plain) structs[tokens[i + 1].text] = members;
    }
    return structs;
}

bool sameMemberTypes(const std::vector<Member>& a, const std::vector<Member>& b) {
    if (a.size() != b.size() || a.empty()) return false;
    for (size_t m = 0; m < a.size(); ++m)
        if (a[m].type != b[m].type) return false;
    return true;
}

// The type `name` is declared with in tokens[from, at): the nearest "Type name" before it.
std::optional<std::string> declaredType(const std::vector<Token>& tokens, size_t from, size_t at, const std::string& name) {
    for (size_t k = at; k-- > from + 1;)
        if (tokens[k].is(name) && tokens[k].isIdentifier() && tokens[k - 1].isIdentifier() && isTypeLike(tokens[k - 1]) &&
            (tokens[k + 1].is(";") || tokens[k + 1].is(")") || tokens[k + 1].is(",") || tokens[k + 1].is("=") || tokens[k + 1].is(":")))
            return tokens[k - 1].text;
    return std::nullopt;
}

} // namespace

std::vector<Token> convertReturnedStructs(const std::vector<Token>& tokens) {
    const auto structs = structMembers(tokens);
    if (structs.size() < 2) return tokens;
    TokenWriter writer;
    int converted = 0;
    std::optional<std::string> returnType; // of the function whose body holds tokens[i]
    size_t functionStart = 0, bodyEnd = 0;
    int depth = 0;
    for (size_t i = 0; i < tokens.size(); ++i) {
        const Token& token = tokens[i];
        // "Type name(...) {" at the top level starts a function returning Type.
        if (depth == 0 && token.is("(") && i >= 2 && tokens[i - 1].isIdentifier() && tokens[i - 2].isIdentifier()) {
            size_t body = matchingClose(tokens, i) + 1;
            while (body < tokens.size() && !tokens[body].is("{") && !tokens[body].is(";")) ++body;
            if (body < tokens.size() && tokens[body].is("{")) {
                returnType = tokens[i - 2].text;
                functionStart = i;
                bodyEnd = matchingClose(tokens, body);
            }
        }
        if (opensBracket(token)) ++depth;
        if (closesBracket(token)) --depth;
        if (i > bodyEnd) returnType.reset();
        const bool returnsName = token.is("return") && i + 2 < tokens.size() && tokens[i + 1].isIdentifier() && tokens[i + 2].is(";");
        const auto target = returnType ? structs.find(*returnType) : structs.end();
        const auto from = returnsName && target != structs.end() ? declaredType(tokens, functionStart, i, tokens[i + 1].text) : std::nullopt;
        const auto source = from && *from != *returnType ? structs.find(*from) : structs.end();
        if (source == structs.end() || !sameMemberTypes(source->second, target->second)) {
            writer.keep(token);
            continue;
        }
        const std::string value = "iblkit_converted_" + std::to_string(converted++);
        std::string text = "{ " + *returnType + " " + value + " ;";
        for (size_t m = 0; m < target->second.size(); ++m)
            text += " " + value + " . " + target->second[m].name + " = " + tokens[i + 1].text + " . " + source->second[m].name + " ;";
        writer.replace(token, text + " return " + value + " ; }");
        writer.drop(TokenSpan(tokens).subspan(i + 1, 2));
        i += 2;
    }
    return writer.finish();
}

} // namespace iblkit::lowering
