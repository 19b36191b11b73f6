#include "unreachable_declarations.hpp"

#include "token_edit.hpp"
#include "unsupported_features.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace iblkit::lowering {
namespace {

struct Declaration {
    size_t begin = 0, end = 0; // tokens [begin, end)
    std::set<std::string> defines;
    std::set<std::string> uses;
    bool unsupported = false;
    bool function = false; // a function's definition or prototype, or a struct with member functions
    // Dropped where the entry point does not reach it: a function, or what holds a feature
    // glslang lacks. Everything else is kept, and what it names with it.
    bool droppable() const { return function || unsupported; }
};

// Where the top-level declaration that starts at `begin` ends: after its ";" at depth 0, or after
// the "}" of its body (with the ";" or the declarators that follow a struct's).
size_t declarationEnd(const std::vector<Token>& tokens, size_t begin) {
    if (tokens[begin].kind == TokenKind::Directive) return begin + 1;
    const bool aggregate = tokens[begin].is("struct") || tokens[begin].is("class");
    int depth = 0;
    for (size_t i = begin; i + 1 < tokens.size(); ++i) {
        const Token& token = tokens[i];
        if (opensBracket(token)) ++depth;
        if (closesBracket(token) && --depth == 0 && token.is("}")) {
            if (tokens[i + 1].is(";")) return i + 2;
            if (!aggregate) return i + 1;
        }
        if (depth == 0 && token.is(";")) return i + 1;
        if (depth < 0) return i + 1; // unbalanced: glslang will say where
    }
    return tokens.size() - 1;
}

// A name a declaration introduces: an identifier at depth 0 (or a constant buffer's member at
// depth 1) followed by what follows a declared name, and not a semantic or register after ":".
bool introducesName(const std::vector<Token>& tokens, size_t i, size_t end) {
    if (!tokens[i].isIdentifier() || i + 1 >= end || (i > 0 && tokens[i - 1].is(":"))) return false;
    const Token& next = tokens[i + 1];
    return next.is("(") || next.is(":") || next.is(";") || next.is("=") || next.is("[") || next.is(",") || next.is("{");
}

Declaration readDeclaration(const std::vector<Token>& tokens, size_t begin, size_t end) {
    Declaration declaration{begin, end, {}, {}, false};
    const bool buffer = tokens[begin].is("cbuffer") || tokens[begin].is("tbuffer");
    const bool aggregate = tokens[begin].is("struct") || tokens[begin].is("class");
    int depth = 0;
    for (size_t i = begin; i < end; ++i) {
        const Token& token = tokens[i];
        if (closesBracket(token)) --depth;
        if (token.isIdentifier()) {
            declaration.uses.insert(token.text);
            declaration.unsupported |= glslangLacks(token.text);
            const bool declared = (depth == 0 || (buffer && depth == 1)) && introducesName(tokens, i, end);
            if (declared || (aggregate && i == begin + 1)) declaration.defines.insert(token.text);
            // A function's prototype (Type Name(...);) goes with the function, reached or not.
            if (declared && depth == 0 && !buffer && !aggregate && tokens[i + 1].is("(")) declaration.function = true;
        }
        // [patchconstantfunc("PatchConstants")] names a function in a string.
        if (token.kind == TokenKind::String && token.text.size() > 2) declaration.uses.insert(token.text.substr(1, token.text.size() - 2));
        if (depth == 0 && token.is("{") && !buffer && !aggregate && i > begin && (tokens[i - 1].is(")") || tokens[i - 2].is(":"))) declaration.function = true;
        // A member function's body: a struct with one is dropped unreached, as a function is.
        if (depth == 1 && aggregate && token.is("{") && (tokens[i - 1].is(")") || tokens[i - 1].is("const"))) declaration.function = true;
        if (opensBracket(token)) ++depth;
    }
    return declaration;
}

std::vector<Declaration> topLevelDeclarations(const std::vector<Token>& tokens) {
    std::vector<Declaration> declarations;
    for (size_t begin = 0; begin + 1 < tokens.size();) {
        const size_t end = declarationEnd(tokens, begin);
        declarations.push_back(readDeclaration(tokens, begin, end));
        begin = end;
    }
    return declarations;
}

std::vector<bool> reachedFrom(const std::vector<Declaration>& declarations, const std::string& entryPoint) {
    std::map<std::string, std::vector<size_t>> definers;
    for (size_t d = 0; d < declarations.size(); ++d)
        for (const auto& name : declarations[d].defines) definers[name].push_back(d);
    std::vector<bool> reached(declarations.size(), false);
    std::vector<size_t> pending;
    // Roots: the entry point, and what is kept whether reached or not (a resource the reflection
    // lists keeps the struct it holds, and that struct's member functions what they call).
    for (size_t d = 0; d < declarations.size(); ++d) {
        const auto& declaration = declarations[d];
        if (declaration.defines.empty() || declaration.defines.count(entryPoint) || !declaration.droppable()) pending.push_back(d);
    }
    while (!pending.empty()) {
        const size_t d = pending.back();
        pending.pop_back();
        if (reached[d]) continue;
        reached[d] = true;
        for (const auto& name : declarations[d].uses)
            if (const auto found = definers.find(name); found != definers.end())
                for (const size_t other : found->second)
                    if (!reached[other]) pending.push_back(other);
    }
    return reached;
}

} // namespace

std::vector<Token> dropUnreachableUnsupported(const std::vector<Token>& tokens, const std::string& entryPoint) {
    const auto declarations = topLevelDeclarations(tokens);
    const bool entryDefined = std::any_of(declarations.begin(), declarations.end(),
                                          [&](const Declaration& d) { return d.defines.count(entryPoint) > 0; });
    if (entryPoint.empty() || !entryDefined) return tokens;
    const auto reached = reachedFrom(declarations, entryPoint);
    TokenWriter writer;
    for (size_t d = 0; d < declarations.size(); ++d) {
        const auto span = TokenSpan(tokens).subspan(declarations[d].begin, declarations[d].end - declarations[d].begin);
        if (!reached[d] && declarations[d].droppable()) writer.drop(span);
        else writer.keep(span);
    }
    writer.keep(tokens.back());
    return writer.finish();
}

} // namespace iblkit::lowering
