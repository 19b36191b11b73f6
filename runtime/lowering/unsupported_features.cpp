#include "unsupported_features.hpp"

#include "token_edit.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <string>

namespace iblkit::lowering {
namespace {

const std::string kFrontend = " is not supported by glslang's HLSL frontend";
const std::string kFrontendPlural = " are not supported by glslang's HLSL frontend";

std::string intrinsicMessage(const std::string& name, const char* shaderModel, const char* instead) {
    return std::string("the Shader Model ") + shaderModel + " intrinsic '" + name + "'" + kFrontend + ": " + instead;
}

// int64_t and its vectors and matrices, and uint64_t's (int64_t2, uint64_t3x3): glslang's HLSL
// frontend knows the uint64_t scalar only.
bool isSixtyFourBitTypeGlslangLacks(std::string_view name) {
    for (const std::string_view base : {"int64_t", "uint64_t"}) {
        if (!name.starts_with(base)) continue;
        const auto shape = name.substr(base.size());
        if (shape.empty()) return base == "int64_t";
        return std::all_of(shape.begin(), shape.end(), [](char c) { return (c >= '1' && c <= '4') || c == 'x'; });
    }
    return false;
}

// What glslang lacks, named: its message, and whether a shader may define it itself (an
// intrinsic's polyfill for older compilers).
struct Lack {
    std::string message; // "" for a name glslang has
    bool definable = false;
};

Lack lackOf(const std::string& name) {
    static const std::set<std::string, std::less<>> rayTracingTypes{"RaytracingAccelerationStructure", "RayQuery"};
    static const std::set<std::string, std::less<>> rayTracingCalls{"TraceRay", "TraceRayInline", "ReportHit", "CallShader"};
    static const std::set<std::string, std::less<>> packing{"pack_u8",      "pack_s8",      "pack_clamp_u8", "pack_clamp_s8",
                                                            "unpack_u8u16", "unpack_u8u32", "unpack_s8s16",  "unpack_s8s32"};
    static const std::set<std::string, std::less<>> waveMatch{
        "WaveMatch", "WaveMultiPrefixSum", "WaveMultiPrefixProduct", "WaveMultiPrefixCountBits",
        "WaveMultiPrefixBitAnd", "WaveMultiPrefixBitOr", "WaveMultiPrefixBitXor"};
    if (name == "interface") return {"an interface" + kFrontend + ": write a struct with member functions and call them directly"};
    if (rayTracingTypes.contains(name)) return {"ray tracing ('" + name + "')" + kFrontend};
    if (rayTracingCalls.contains(name)) return {"ray tracing ('" + name + "')" + kFrontend, true};
    if (name == "ResourceDescriptorHeap" || name == "SamplerDescriptorHeap")
        return {"Shader Model 6.6 dynamic resources ('" + name + "')" + kFrontendPlural +
                ": declare each resource, with a register or [[vk::binding]]"};
    if (name == "uint8_t4_packed" || name == "int8_t4_packed")
        return {"the Shader Model 6.6 type '" + name + "'" + kFrontend + ": hold the four bytes in a uint"};
    if (packing.contains(name)) return {intrinsicMessage(name, "6.6", "shift and mask the bytes of a uint"), true};
    if (waveMatch.contains(name)) return {intrinsicMessage(name, "6.5", "build it from WaveActiveBallot"), true};
    if (isSixtyFourBitTypeGlslangLacks(name))
        return {"'" + name + "'" + kFrontend + ": it has 64-bit integers only as uint64_t scalars"};
    if (name == "dot2add" || name == "dot4add_u8packed" || name == "dot4add_i8packed")
        return {intrinsicMessage(name, "6.4", "write the dot product"), true};
    return {};
}

// Whether tokens[i] names a struct the shader defines, or a function: a type before it, its
// parameter list, then its body (or a semantic).
bool definesStructOrFunction(const std::vector<Token>& tokens, size_t i) {
    if (i > 0 && tokens[i - 1].is("struct")) return true;
    if (i == 0 || i + 1 >= tokens.size() || !tokens[i + 1].is("(")) return false;
    const Token& before = tokens[i - 1];
    if (!before.isIdentifier() || !isTypeLike(before)) return false;
    const size_t close = matchingClose(tokens, i + 1);
    return close + 1 < tokens.size() && (tokens[close + 1].is("{") || tokens[close + 1].is(":"));
}

// "(uint64_t)100000" or "uint64_t(100000)": glslang fails to fold a literal into a 64-bit
// integer, with "'' : unsupported construction" at the start of the statement.
void refuseLiteralCastsToUint64(const std::vector<Token>& tokens) {
    for (size_t i = 0; i + 3 < tokens.size(); ++i) {
        const bool cast = tokens[i].is("(") && tokens[i + 1].is("uint64_t") && tokens[i + 2].is(")");
        const bool constructor = tokens[i].is("uint64_t") && tokens[i + 1].is("(") && tokens[i + 3].is(")");
        const Token& literal = tokens[cast ? i + 3 : i + 2];
        if ((cast || constructor) && literal.kind == TokenKind::Number)
            refuse(tokens[cast ? i + 1 : i], "a literal converted to uint64_t ('" + literal.text + "') is not supported by "
                                             "glslang's HLSL frontend: assign it to a uint64_t variable first");
    }
}

} // namespace

bool glslangLacks(const std::string& name) { return !lackOf(name).message.empty(); }

void refuseUnsupportedFeatures(const std::vector<Token>& tokens) {
    refuseLiteralCastsToUint64(tokens);
    std::set<std::string, std::less<>> defined;
    for (size_t i = 0; i < tokens.size(); ++i)
        if (tokens[i].isIdentifier() && lackOf(tokens[i].text).definable && definesStructOrFunction(tokens, i))
            defined.insert(tokens[i].text);
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (!tokens[i].isIdentifier() || followsMemberAccess(tokens, i)) continue;
        const auto lack = lackOf(tokens[i].text);
        if (!lack.message.empty() && !(lack.definable && defined.contains(tokens[i].text))) refuse(tokens[i], lack.message);
    }
}

} // namespace iblkit::lowering
