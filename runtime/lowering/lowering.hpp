#pragma once

#include "vulkan_attributes.hpp"

#include <set>
#include <string>
#include <vector>

namespace iblkit::lowering {

enum class HlslVersion { Hlsl2018, Hlsl2021 };

struct LoweredSource {
    std::string text;     // the preprocessed text with every construct lowered, #line kept
    bool changed = false; // false: the shader needs no lowering, and its own text is what to parse
    VulkanAttributes vulkan;
    std::vector<std::string> warnings; // one line each: attributes not honoured, minimum precision at 32 bits
    std::vector<std::string> edits;    // what was lowered, by id ("select-and-or", "enums", ...): kit_edits.hpp
    std::set<std::string> packedMembers; // the names declared with ": packoffset(...)"
};

// HLSL as DXC reads it -> HLSL as glslang's frontend reads it, on the tokens of the
// preprocessed text (glslang's, with its #line directives, so that every line still names its
// file and line). For HLSL 2021: select/and/or (intrinsics.hpp), enums (enums.hpp), namespaces
// (namespaces.hpp), and a refusal by name for what cannot be lowered (refusals.hpp); for
// every version: the [[vk::...]] attributes (vulkan_attributes.hpp) and the 16-bit types
// (sixteen_bit.hpp). Throws LoweringError.
// enable16BitTypes: DXC's float16_t, int16_t and uint16_t under glslang's names (sixteen_bit.hpp).
// entryPoint: what the unreachable declarations are judged from (unreachable_declarations.hpp);
// "" keeps every declaration.
LoweredSource lowerHlsl(const std::string& preprocessed, const std::string& sourceName, HlslVersion version,
                        bool enable16BitTypes = false, const std::string& entryPoint = "");

} // namespace iblkit::lowering
