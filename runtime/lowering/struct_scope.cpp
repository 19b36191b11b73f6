#include "struct_scope.hpp"

#include "token_edit.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <string>

namespace iblkit::lowering {
namespace {

struct Hoisted {
    size_t begin = 0, end = 0; // tokens [begin, end) of the member declaration, ";" included
    std::vector<std::string> names;
    std::string value; // a static member's initializer, as text: what its uses in the struct become
    bool function = false; // a static member function: it goes after the struct, whose type it may use
};

// "static const int N = 16 * 4;": the tokens of "16 * 4", or an empty range.
std::pair<size_t, size_t> initializerOf(const std::vector<Token>& tokens, size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i)
        if (tokens[i].is("=")) return {i + 1, end - 1};
    return {end, end};
}

// The end of the member declaration that starts at `at`: after its ";" at the body's depth, or
// after a member function's body.
size_t memberEnd(const std::vector<Token>& tokens, size_t at, size_t bodyClose) {
    int depth = 0;
    bool call = false;
    for (size_t i = at; i < bodyClose; ++i) {
        if (tokens[i].is("(")) call = true;
        if (opensBracket(tokens[i])) ++depth;
        if (closesBracket(tokens[i])) --depth;
        if (depth == 0 && tokens[i].is(";")) return i + 1;
        if (depth == 0 && call && tokens[i].is("}")) return tokens[i + 1].is(";") ? i + 2 : i + 1;
    }
    return bodyClose;
}

// A static member function's name, or "".
std::string staticFunctionName(const std::vector<Token>& tokens, size_t at, size_t end) {
    bool isStatic = false;
    for (size_t i = at; i + 1 < end; ++i) {
        if (tokens[i].is("static")) isStatic = true;
        if (tokens[i].is("=") || tokens[i].is(";")) return "";
        if (tokens[i + 1].is("(")) return isStatic && tokens[i].isIdentifier() && tokens[end - 1].is("}") ? tokens[i].text : "";
    }
    return "";
}

// A static member with its value, or an enum: what the declaration at `at` names, or nothing.
std::vector<std::string> hoistableNames(const std::vector<Token>& tokens, size_t at, size_t end) {
    std::vector<std::string> names;
    if (tokens[at].is("enum")) {
        size_t i = at + 1;
        if (tokens[i].is("class") || tokens[i].is("struct")) ++i;
        if (tokens[i].isIdentifier()) names.push_back(tokens[i].text);
        for (; i < end && !tokens[i].is("{"); ++i) {}
        if (i >= end) return names;
        const size_t close = matchingClose(tokens, i);
        const bool scoped = tokens[at + 1].is("class") || tokens[at + 1].is("struct");
        if (!scoped)
            for (const auto& [first, last] : splitAtCommas(tokens, i + 1, close))
                if (first < last && tokens[first].isIdentifier()) names.push_back(tokens[first].text);
        return names;
    }
    bool isStatic = false;
    size_t equals = end;
    for (size_t i = at; i < end; ++i) {
        if (tokens[i].is("static")) isStatic = true;
        if (tokens[i].is("(") || tokens[i].is("{")) return {}; // a member function
        if (tokens[i].is("=") && equals == end) equals = i;
    }
    if (!isStatic || equals == end) return {};
    size_t name = equals - 1;
    while (name > at && tokens[name].is("]")) name = name - 1; // an array's size: "X[4] = {...}"
    while (name > at && !tokens[name].isIdentifier()) --name;
    if (tokens[name].isIdentifier()) names.push_back(tokens[name].text);
    return names;
}

} // namespace

std::vector<Token> hoistStructScopeDeclarations(const std::vector<Token>& tokens) {
    TokenWriter writer;
    for (size_t i = 0; i < tokens.size(); ++i) {
        const bool structBody = (tokens[i].is("struct") || tokens[i].is("class")) && i + 2 < tokens.size() &&
                                tokens[i + 1].isIdentifier() && tokens[i + 2].is("{") && !(i > 0 && tokens[i - 1].is("enum"));
        if (!structBody) {
            writer.keep(tokens[i]);
            continue;
        }
        const std::string& structName = tokens[i + 1].text;
        const size_t open = i + 2, close = matchingClose(tokens, open);
        std::vector<Hoisted> hoisted;
        for (size_t member = open + 1; member < close;) {
            const size_t end = memberEnd(tokens, member, close);
            if (auto function = staticFunctionName(tokens, member, end); !function.empty()) {
                hoisted.push_back({member, end, {function}, "", true});
                member = end;
                continue;
            }
            auto names = hoistableNames(tokens, member, end);
            if (!names.empty()) {
                const auto [first, last] = initializerOf(tokens, member, end);
                const bool scalar = !tokens[member].is("enum") && first < last && !tokens[first].is("{");
                const std::string value = scalar ? "(" + spacedText(TokenSpan(tokens).subspan(first, last - first)) + ")" : "";
                hoisted.push_back({member, end, std::move(names), value});
            }
            member = end;
        }
        if (hoisted.empty()) {
            writer.keep(tokens[i]);
            continue;
        }
        // Inside the struct, a hoisted name is the namespace's; a static member with a value is its
        // value, which glslang takes where it needs a constant (an array's size).
        std::map<std::string, std::string> names;
        for (const auto& h : hoisted)
            for (const auto& name : h.names) names[name] = h.value.empty() ? structName + "::" + name : h.value;
        const auto keepQualified = [&](size_t k) {
            const Token& token = tokens[k];
            const auto found = token.isIdentifier() ? names.find(token.text) : names.end();
            if (found != names.end() && !followsMemberAccess(tokens, k) && !followsQualifier(tokens, k))
                writer.replace(token, found->second);
            else writer.keep(token);
        };
        // In the namespace, its names need no qualifier.
        const auto writeNamespace = [&](bool functions, const SourcePlace& place, std::string_view leading) {
            writer.add("namespace " + structName + " {", place, leading);
            for (const auto& h : hoisted)
                if (h.function == functions) writer.keep(TokenSpan(tokens).subspan(h.begin, h.end - h.begin));
            writer.add("}", place);
        };
        const bool anyFunction = std::any_of(hoisted.begin(), hoisted.end(), [](const Hoisted& h) { return h.function; });
        const bool anyValue = std::any_of(hoisted.begin(), hoisted.end(), [](const Hoisted& h) { return !h.function; });
        if (anyValue) writeNamespace(false, tokens[i].place, tokens[i].leading);
        writer.add(tokens[i].text, tokens[i].place, anyValue ? " " : tokens[i].leading);
        size_t next = 0;
        for (size_t k = i + 1; k <= close; ++k) {
            if (next < hoisted.size() && k == hoisted[next].begin) {
                writer.drop(TokenSpan(tokens).subspan(k, hoisted[next].end - k));
                k = hoisted[next++].end - 1;
                continue;
            }
            keepQualified(k);
        }
        i = close;
        if (anyFunction) {
            if (i + 1 < tokens.size() && tokens[i + 1].is(";")) writer.keep(tokens[++i]);
            writeNamespace(true, tokens[close].place, " ");
        }
    }
    return writer.finish();
}

} // namespace iblkit::lowering
