#include "type_spellings.hpp"

#include "token_edit.hpp"

#include <regex>
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

// "min16float3x3" -> "half3x3": glslang has minimum-precision scalars and vectors but no
// matrices; half is what it makes of min16float (16 bits with -enable-16bit-types, else 32, as DXC).
std::string matrixOfMinimumPrecision(const std::string& name) {
    for (const auto& [prefix, spelled] : {std::pair<std::string_view, std::string_view>{"min16float", "half"},
                                          {"min10float", "half"}, {"min16int", "int"}, {"min12int", "int"},
                                          {"min16uint", "uint"}}) {
        if (!name.starts_with(prefix)) continue;
        const auto shape = name.substr(prefix.size());
        const bool matrix = shape.size() == 3 && shape[1] == 'x' && shape[0] >= '1' && shape[0] <= '4' && shape[2] >= '1' &&
                            shape[2] <= '4';
        return matrix ? std::string(spelled) + shape : "";
    }
    return "";
}

// "1.xxxx", "2.0.xy": a literal swizzled as HLSL lets it be (the float 1.0 made a float4), which
// glslang reads as a malformed number; as "(1.0).xxxx" it reads it. "" for any other token.
bool isSwizzle(const Token& token) {
    static const std::regex kSwizzle(R"([xyzw]{1,4}|[rgba]{1,4})");
    return token.isIdentifier() && std::regex_match(token.text, kSwizzle);
}

std::string swizzledLiteral(const Token& token) {
    static const std::regex kSwizzled(R"(([0-9]+(\.[0-9]*)?([eE][+-]?[0-9]+)?[fFhH]?)\.([xyzw]{1,4}|[rgba]{1,4}))");
    std::smatch match;
    if (token.kind != TokenKind::Number || !std::regex_match(token.text, match, kSwizzled)) return "";
    const std::string number = match[1].str();
    const bool isFloat = number.find_first_of(".eE") != std::string::npos;
    return "(" + number + (isFloat ? "" : ".0") + ")." + match[4].str();
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
        if (const auto literal = swizzledLiteral(token); !literal.empty()) {
            writer.replace(token, literal);
            continue;
        }
        // glslang's preprocessor writes "2.xx" as "2. xx".
        if (token.kind == TokenKind::Number && token.text.back() == '.' && i + 1 < tokens.size() &&
            isSwizzle(tokens[i + 1])) {
            writer.replace(token, "(" + token.text + "0)." + tokens[i + 1].text);
            writer.drop(tokens[++i]);
            continue;
        }
        if (const auto matrix = member || !token.isIdentifier() ? "" : matrixOfMinimumPrecision(token.text); !matrix.empty()) {
            writer.replace(token, matrix);
            continue;
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
