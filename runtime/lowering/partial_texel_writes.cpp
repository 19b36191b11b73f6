#include "partial_texel_writes.hpp"

#include "token_edit.hpp"

#include <map>
#include <optional>
#include <string>

namespace iblkit::lowering {
namespace {

// The coordinates each storage resource takes: RWTexture2D<T> is indexed by a uint2.
std::optional<std::string> coordinateType(const std::string& type) {
    static const std::map<std::string, std::string, std::less<>> kCoordinates{
        {"RWBuffer", "uint"},
        {"RWTexture1D", "uint"},
        {"RWTexture1DArray", "uint2"},
        {"RWTexture2D", "uint2"},
        {"RWTexture2DArray", "uint3"},
        {"RWTexture3D", "uint3"},
        {"RasterizerOrderedBuffer", "uint"},
        {"RasterizerOrderedTexture1D", "uint"},
        {"RasterizerOrderedTexture1DArray", "uint2"},
        {"RasterizerOrderedTexture2D", "uint2"},
        {"RasterizerOrderedTexture2DArray", "uint3"},
        {"RasterizerOrderedTexture3D", "uint3"}};
    const auto found = kCoordinates.find(type);
    if (found == kCoordinates.end()) return std::nullopt;
    return found->second;
}

struct StorageTexels {
    std::string texel = "float4"; // RWTexture2D without <T> holds float4
    std::string coordinates;
    size_t arrayDimensions = 0;   // RWTexture2D<float4> Textures[4][2]: 2
};

// "RWTexture2D<T> name[...]" with its type at tokens[i]: the name's index and what it holds.
std::optional<std::pair<size_t, StorageTexels>> readDeclaration(const std::vector<Token>& tokens, size_t i) {
    if (!tokens[i].isIdentifier() || followsMemberAccess(tokens, i)) return std::nullopt;
    const auto coordinates = coordinateType(tokens[i].text);
    if (!coordinates) return std::nullopt;
    StorageTexels texels{"float4", *coordinates, 0};
    size_t at = i + 1;
    if (at < tokens.size() && tokens[at].is("<")) {
        const size_t begin = at + 1;
        while (at < tokens.size() && !tokens[at].is(">")) {
            if (tokens[at].is(";") || tokens[at].is("{") || tokens[at].is("(")) return std::nullopt;
            ++at;
        }
        if (at >= tokens.size()) return std::nullopt;
        texels.texel = spacedText(TokenSpan(tokens).subspan(begin, at - begin));
        ++at;
    }
    if (at >= tokens.size() || !tokens[at].isIdentifier()) return std::nullopt;
    const size_t name = at++;
    while (at < tokens.size() && tokens[at].is("[")) {
        at = matchingClose(tokens, at) + 1;
        ++texels.arrayDimensions;
    }
    return std::make_pair(name, texels);
}

bool isAssignmentOperator(const Token& token) {
    for (const char* spelling : {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>="})
        if (token.is(spelling)) return true;
    return false;
}

bool startsStatement(const std::vector<Token>& tokens, size_t i) {
    if (i == 0) return false;
    const Token& before = tokens[i - 1];
    return before.is(";") || before.is("{") || before.is("}") || before.is(")") || before.is("else") || before.is(":");
}

// An index read twice must give the same resource both times.
bool freeOfSideEffects(TokenSpan tokens) {
    for (const auto& token : tokens)
        if (token.is("(") || token.is("++") || token.is("--") || isAssignmentOperator(token)) return false;
    return true;
}

struct PartialWrite {
    size_t begin = 0;       // the resource's name
    size_t coordinates = 0; // the "[" of the texel's coordinates
    size_t components = 0;  // the "." before the components written
    size_t end = 0;         // the ";"
};

// `name[array]...[coordinates].components OP value;` at tokens[i], or nothing.
std::optional<PartialWrite> readPartialWrite(const std::vector<Token>& tokens, size_t i, const StorageTexels& texels) {
    if (!startsStatement(tokens, i)) return std::nullopt;
    PartialWrite write{i, 0, 0, 0};
    size_t at = i + 1;
    for (size_t group = 0; group <= texels.arrayDimensions; ++group) {
        if (at >= tokens.size() || !tokens[at].is("[")) return std::nullopt;
        const size_t close = matchingClose(tokens, at);
        if (group < texels.arrayDimensions && !freeOfSideEffects(TokenSpan(tokens).subspan(at, close - at))) return std::nullopt;
        write.coordinates = at;
        at = close + 1;
    }
    if (at + 2 >= tokens.size() || !tokens[at].is(".") || !tokens[at + 1].isIdentifier() || !isAssignmentOperator(tokens[at + 2]))
        return std::nullopt;
    write.components = at;
    int depth = 0;
    for (size_t k = at + 3; k < tokens.size(); ++k) {
        if (opensBracket(tokens[k])) ++depth;
        if (closesBracket(tokens[k]) && --depth < 0) return std::nullopt;
        if (depth == 0 && tokens[k].is(";")) {
            write.end = k;
            return write;
        }
    }
    return std::nullopt;
}

std::string text(const std::vector<Token>& tokens, size_t begin, size_t end) {
    return spacedText(TokenSpan(tokens).subspan(begin, end - begin));
}

std::string readModifyWrite(const std::vector<Token>& tokens, const PartialWrite& write, const StorageTexels& texels, int number) {
    const std::string at = "iblkit_texel_at_" + std::to_string(number);
    const std::string value = "iblkit_texel_" + std::to_string(number);
    const size_t close = matchingClose(tokens, write.coordinates);
    const std::string resource = text(tokens, write.begin, write.coordinates) + " [ " + at + " ]";
    return "{ " + texels.coordinates + " " + at + " = " + text(tokens, write.coordinates + 1, close) + " ; " + texels.texel +
           " " + value + " = " + resource + " ; " + value + " " + text(tokens, write.components, write.end) + " ; " +
           resource + " = " + value + " ; }";
}

// The StorageTexels each name is declared with, in token order: the latest declaration before a
// use is the one it names.
template <typename Visit>
void forEachUseOfStorage(const std::vector<Token>& tokens, Visit visit) {
    std::map<std::string, StorageTexels> declared;
    std::map<size_t, size_t> declarationNames;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (const auto declaration = readDeclaration(tokens, i)) {
            declared[tokens[declaration->first].text] = declaration->second;
            declarationNames[declaration->first] = i;
        }
        const auto found = tokens[i].isIdentifier() && !declarationNames.contains(i) && !followsMemberAccess(tokens, i)
                               ? declared.find(tokens[i].text)
                               : declared.end();
        i = visit(i, found != declared.end() ? &found->second : nullptr);
    }
}

} // namespace

std::vector<Token> convertStorageLoadCoordinates(const std::vector<Token>& tokens) {
    TokenWriter writer;
    forEachUseOfStorage(tokens, [&](size_t i, const StorageTexels* texels) {
        // name [array indices]... . Load ( argument )
        size_t at = i + 1;
        for (size_t group = 0; texels && group < texels->arrayDimensions && at < tokens.size() && tokens[at].is("["); ++group)
            at = matchingClose(tokens, at) + 1;
        const bool load = texels && at + 2 < tokens.size() && tokens[at].is(".") && tokens[at + 1].is("Load") && tokens[at + 2].is("(");
        const size_t close = load ? matchingClose(tokens, at + 2) : 0;
        if (!load || close == at + 3 || splitAtCommas(tokens, at + 3, close).size() != 1) {
            writer.keep(tokens[i]);
            return i;
        }
        writer.keep(TokenSpan(tokens).subspan(i, at + 3 - i));
        const std::string coordinates = texels->coordinates.substr(1); // uint2 -> int2, as Load declares it
        writer.add("( " + coordinates + " ) (", tokens[at + 3].place, tokens[at + 3].leading);
        Token first = tokens[at + 3];
        first.leading = " ";
        writer.keep(first);
        writer.keep(TokenSpan(tokens).subspan(at + 4, close - at - 4));
        writer.add(")", tokens[close].place, "");
        writer.keep(tokens[close]);
        return close;
    });
    return writer.finish();
}

std::vector<Token> lowerPartialTexelWrites(const std::vector<Token>& tokens) {
    TokenWriter writer;
    int written = 0;
    forEachUseOfStorage(tokens, [&](size_t i, const StorageTexels* texels) {
        const auto write = texels ? readPartialWrite(tokens, i, *texels) : std::nullopt;
        if (!write) {
            writer.keep(tokens[i]);
            return i;
        }
        writer.replace(tokens[i], readModifyWrite(tokens, *write, *texels, written++));
        writer.drop(TokenSpan(tokens).subspan(i + 1, write->end - i));
        return write->end;
    });
    return writer.finish();
}

} // namespace iblkit::lowering
