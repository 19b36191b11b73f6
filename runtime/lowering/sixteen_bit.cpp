#include "sixteen_bit.hpp"

#include "token_edit.hpp"

#include <array>
#include <cctype>
#include <set>

namespace iblkit::lowering {
namespace {

struct Spelling {
    std::string_view dxc;
    std::string_view glslang;
    bool sixteenBit = false; // DXC takes it only with -enable-16bit-types
};

// Shader Model 6.2's explicit-width types. The 32- and 64-bit ones are the plain types under
// other names; glslang knows none of them but uint64_t.
constexpr std::array kSpellings{Spelling{"float16_t", "half", true}, Spelling{"int16_t", "min16int", true},
                                Spelling{"uint16_t", "min16uint", true}, Spelling{"float32_t", "float"},
                                Spelling{"int32_t", "int"}, Spelling{"uint32_t", "uint"},
                                Spelling{"float64_t", "double"}};

// "float16_t3x3" -> {half, "3x3"}: a DXC 16-bit type with its vector or matrix suffix.
const Spelling* explicitType(const std::string& name, std::string& suffix) {
    for (const auto& spelling : kSpellings) {
        if (name.rfind(spelling.dxc, 0) != 0) continue;
        suffix = name.substr(spelling.dxc.size());
        const bool shaped = suffix.empty() || (suffix.size() == 1 && suffix[0] >= '1' && suffix[0] <= '4') ||
                            (suffix.size() == 3 && suffix[1] == 'x' && suffix[0] >= '1' && suffix[0] <= '4' &&
                             suffix[2] >= '1' && suffix[2] <= '4');
        if (shaped) return &spelling;
    }
    return nullptr;
}

bool isMinimumPrecision(const std::string& name) {
    for (const std::string_view type : {"min16float", "min10float", "min16int", "min12int", "min16uint"})
        if (name.rfind(type, 0) == 0) return true;
    return false;
}

} // namespace

std::vector<Token> lowerSixteenBitTypes(const std::vector<Token>& tokens, bool enabled, std::vector<std::string>& warnings) {
    TokenWriter writer;
    std::set<std::string> minimumPrecision;
    for (size_t i = 0; i < tokens.size(); ++i) {
        const Token& token = tokens[i];
        const bool member = followsMemberAccess(tokens, i) || followsQualifier(tokens, i);
        std::string suffix;
        const Spelling* spelling = token.isIdentifier() && !member ? explicitType(token.text, suffix) : nullptr;
        if (spelling && spelling->sixteenBit && !enabled)
            refuse(token, "'" + token.text + "' is a 16-bit type: compile with -enable-16bit-types");
        if (spelling) {
            writer.replace(token, std::string(spelling->glslang) + suffix);
            continue;
        }
        if (!enabled && token.isIdentifier() && !member && isMinimumPrecision(token.text)) minimumPrecision.insert(token.text);
        writer.keep(token);
    }
    if (!minimumPrecision.empty()) {
        std::string names;
        for (const auto& name : minimumPrecision) names += (names.empty() ? "" : ", ") + name;
        warnings.push_back(tokens.front().place.file + ": warning: " + names +
                           " compiled at 32 bits (minimum precision without -enable-16bit-types; docs/compiler.md)");
    }
    return writer.finish();
}

} // namespace iblkit::lowering
