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

// The message for a name that needs what glslang lacks, or "" for any other name.
std::string messageFor(const std::string& name) {
    static const std::set<std::string, std::less<>> rayTracing{
        "RaytracingAccelerationStructure", "RayQuery", "TraceRay", "TraceRayInline", "ReportHit", "CallShader"};
    static const std::set<std::string, std::less<>> packing{
        "pack_u8", "pack_s8", "pack_clamp_u8", "pack_clamp_s8", "unpack_u8u16",
        "unpack_u8u32", "unpack_s8s16", "unpack_s8s32", "uint8_t4_packed", "int8_t4_packed"};
    static const std::set<std::string, std::less<>> waveMatch{
        "WaveMatch", "WaveMultiPrefixSum", "WaveMultiPrefixProduct", "WaveMultiPrefixCountBits",
        "WaveMultiPrefixBitAnd", "WaveMultiPrefixBitOr", "WaveMultiPrefixBitXor"};
    if (name == "interface")
        return "an interface" + kFrontend + ": write a struct with member functions and call them directly";
    if (rayTracing.contains(name)) return "ray tracing ('" + name + "')" + kFrontend;
    if (name == "ResourceDescriptorHeap" || name == "SamplerDescriptorHeap")
        return "Shader Model 6.6 dynamic resources ('" + name + "')" + kFrontendPlural +
               ": declare each resource, with a register or [[vk::binding]]";
    if (packing.contains(name)) return intrinsicMessage(name, "6.6", "shift and mask the bytes of a uint");
    if (waveMatch.contains(name)) return intrinsicMessage(name, "6.5", "build it from WaveActiveBallot");
    if (isSixtyFourBitTypeGlslangLacks(name))
        return "'" + name + "'" + kFrontend + ": it has 64-bit integers only as uint64_t scalars";
    if (name == "dot2add" || name == "dot4add_u8packed" || name == "dot4add_i8packed")
        return intrinsicMessage(name, "6.4", "write the dot product");
    return "";
}

// Names the shader declares itself: a type or function name right after a type.
std::set<std::string, std::less<>> declaredNames(const std::vector<Token>& tokens) {
    std::set<std::string, std::less<>> names;
    for (size_t i = 1; i < tokens.size(); ++i)
        if (tokens[i].isIdentifier() && (isTypeLike(tokens[i - 1]) || tokens[i - 1].is("struct")))
            names.insert(tokens[i].text);
    return names;
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

void refuseUnsupportedFeatures(const std::vector<Token>& tokens) {
    refuseLiteralCastsToUint64(tokens);
    std::set<std::string, std::less<>> declared;
    bool declaredKnown = false;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (!tokens[i].isIdentifier() || followsMemberAccess(tokens, i)) continue;
        const std::string message = messageFor(tokens[i].text);
        if (message.empty()) continue;
        if (!declaredKnown) declared = declaredNames(tokens), declaredKnown = true;
        if (tokens[i].is("interface") || !declared.contains(tokens[i].text)) refuse(tokens[i], message);
    }
}

} // namespace iblkit::lowering
