#include "resource_locals.hpp"

#include "token_edit.hpp"
#include "unsupported_features.hpp"

#include <algorithm>
#include <set>
#include <string>

namespace iblkit::lowering {
namespace {

bool isResourceType(const Token& token) {
    static const std::set<std::string, std::less<>> kTypes{
        "ByteAddressBuffer", "RWByteAddressBuffer", "StructuredBuffer", "RWStructuredBuffer", "Buffer", "RWBuffer",
        "Texture1D", "Texture1DArray", "Texture2D", "Texture2DArray", "Texture2DMS", "Texture3D", "TextureCube",
        "TextureCubeArray", "RWTexture1D", "RWTexture1DArray", "RWTexture2D", "RWTexture2DArray", "RWTexture3D",
        "SamplerState", "SamplerComparisonState"};
    return token.isIdentifier() && kTypes.contains(token.text);
}

bool isAssignment(const Token& token) {
    static const std::set<std::string, std::less<>> kAssignments{"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>=", "++", "--"};
    return token.kind == TokenKind::Punctuator && kAssignments.contains(token.text);
}

using MemberPath = std::vector<std::string>;

// The name at tokens[i] with the members it selects: gs.geometry.indexBufferIndex.
MemberPath memberPath(const std::vector<Token>& tokens, size_t i) {
    MemberPath path{tokens[i].text};
    while (i + 2 < tokens.size() && tokens[i + 1].is(".") && tokens[i + 2].isIdentifier()) {
        path.push_back(tokens[i + 2].text);
        i += 2;
    }
    return path;
}

// Whether writing one path can change the other: one is the other or holds it.
bool overlap(const MemberPath& a, const MemberPath& b) {
    const size_t common = std::min(a.size(), b.size());
    return std::equal(a.begin(), a.begin() + ptrdiff_t(common), b.begin());
}

// Whether the target at tokens[i] is assigned: an assignment or increment in the expression
// that holds it (up to its ";", "," or ")" at its own depth).
bool assignedAt(const std::vector<Token>& tokens, size_t i, size_t to) {
    if (i > 0 && (tokens[i - 1].is("++") || tokens[i - 1].is("--"))) return true;
    int depth = 0;
    for (size_t k = i + 1; k < to; ++k) {
        if (tokens[k].is("(") || tokens[k].is("[")) ++depth;
        if (tokens[k].is(")") || tokens[k].is("]")) --depth;
        if (depth < 0 || (depth == 0 && (tokens[k].is(";") || tokens[k].is(",") || tokens[k].is("{")))) break;
        if (depth == 0 && isAssignment(tokens[k])) return true;
    }
    return false;
}

// Whether what tokens[begin, end) reads is assigned in tokens[from, to): a variable, or a member
// of it that holds or is held by a member read (gs.vertexPositions[0] = ... leaves
// gs.geometry.indexBufferIndex as it was).
bool assignedLater(const std::vector<Token>& tokens, size_t begin, size_t end, size_t from, size_t to) {
    std::vector<MemberPath> read;
    for (size_t i = begin; i < end; ++i)
        if (tokens[i].isIdentifier() && !followsMemberAccess(tokens, i)) read.push_back(memberPath(tokens, i));
    for (size_t i = from; i < to; ++i) {
        if (!tokens[i].isIdentifier() || followsMemberAccess(tokens, i)) continue;
        const MemberPath written = memberPath(tokens, i);
        const bool readsIt = std::any_of(read.begin(), read.end(), [&](const MemberPath& path) { return overlap(path, written); });
        if (readsIt && assignedAt(tokens, i, to)) return true;
    }
    return false;
}

// The index of the "}" that ends the block holding tokens[at].
size_t blockEnd(const std::vector<Token>& tokens, size_t at) {
    int depth = 0;
    for (size_t i = at; i < tokens.size(); ++i) {
        if (tokens[i].is("{")) ++depth;
        if (tokens[i].is("}") && --depth < 0) return i;
    }
    return tokens.size() - 1;
}

struct Local {
    size_t begin = 0, end = 0;      // the declaration, ";" included
    size_t valueBegin = 0, valueEnd = 0;
    std::string name;
};

// "[const] Type[<...>] name = value;" at i, inside a function's body.
bool readLocal(const std::vector<Token>& tokens, size_t i, Local& local) {
    size_t at = i;
    if (tokens[at].is("const")) ++at;
    if (!isResourceType(tokens[at])) return false;
    ++at;
    if (tokens[at].is("<")) {
        int depth = 0;
        for (; at < tokens.size(); ++at) {
            if (tokens[at].is("<")) ++depth;
            if (tokens[at].is(">") && --depth == 0) break;
            if (tokens[at].is(";") || tokens[at].is("{")) return false;
        }
        ++at;
    }
    if (at + 2 >= tokens.size() || !tokens[at].isIdentifier() || !tokens[at + 1].is("=")) return false;
    local = {i, 0, at + 2, 0, tokens[at].text};
    int depth = 0;
    for (size_t k = at + 2; k < tokens.size(); ++k) {
        if (opensBracket(tokens[k])) ++depth;
        if (closesBracket(tokens[k])) --depth;
        if (depth < 0) return false;
        if (depth == 0 && tokens[k].is(",")) return false; // several declarators: left to glslang
        if (depth == 0 && tokens[k].is(";")) {
            local.valueEnd = k;
            local.end = k + 1;
            return local.valueEnd > local.valueBegin;
        }
    }
    return false;
}

// `Buffers[i]` or `Textures[a][b]`: a name and its indices, which binds as tightly as a name does
// and needs no parentheses where it is written (partial texel writes read it as a resource).
bool isPostfixName(TokenSpan value) {
    if (value.empty() || !value[0].isIdentifier()) return false;
    size_t at = 1;
    while (at < value.size() && value[at].is("[")) at = matchingClose(value, at) + 1;
    return at == value.size();
}

} // namespace

std::vector<Token> inlineResourceLocals(const std::vector<Token>& tokens) {
    std::vector<Token> current = tokens;
    // One local at a time, the text rewritten after each, so that a later local's value may name
    // an earlier one.
    for (bool changed = true; changed;) {
        changed = false;
        int depth = 0;
        for (size_t i = 0; i < current.size() && !changed; ++i) {
            if (current[i].is("{")) ++depth;
            if (current[i].is("}")) --depth;
            Local local;
            const bool statementStart = i > 0 && (current[i - 1].is(";") || current[i - 1].is("{") || current[i - 1].is("}"));
            if (depth == 0 || !statementStart || !readLocal(current, i, local)) continue;
            const size_t end = blockEnd(current, local.end);
            if (assignedLater(current, local.valueBegin, local.valueEnd, local.end, end)) continue;
            // A value glslang cannot read (ResourceDescriptorHeap[i]) stays where its refusal names it.
            const auto lacking = std::any_of(current.begin() + ptrdiff_t(local.valueBegin), current.begin() + ptrdiff_t(local.valueEnd),
                                             [](const Token& token) { return token.isIdentifier() && glslangLacks(token.text); });
            if (lacking) continue;
            const auto valueTokens = TokenSpan(current).subspan(local.valueBegin, local.valueEnd - local.valueBegin);
            const std::string value = isPostfixName(valueTokens) ? spacedText(valueTokens) : "(" + spacedText(valueTokens) + ")";
            TokenWriter writer;
            writer.keep(TokenSpan(current).subspan(0, local.begin));
            writer.drop(TokenSpan(current).subspan(local.begin, local.end - local.begin));
            for (size_t k = local.end; k < current.size(); ++k) {
                const bool use = k < end && current[k].is(local.name) && current[k].isIdentifier() &&
                                 !followsMemberAccess(current, k) && !followsQualifier(current, k);
                if (use) writer.replace(current[k], value);
                else writer.keep(current[k]);
            }
            current = writer.finish();
            changed = true;
        }
    }
    return current;
}

} // namespace iblkit::lowering
