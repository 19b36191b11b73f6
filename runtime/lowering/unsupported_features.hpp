#pragma once

#include "hlsl_tokens.hpp"

#include <vector>

namespace iblkit::lowering {

// Features of DXC's HLSL that glslang's HLSL frontend does not have and no lowering gives it:
// interfaces, ray tracing, Shader Model 6.6 dynamic resources, int64_t and 64-bit vectors,
// literals converted to uint64_t, and the Shader Model 6.4-6.6 intrinsics it lacks (dot2add,
// dot4add_*, pack_* and unpack_*, WaveMatch, WaveMultiPrefix*). The first one used is a
// LoweringError naming it, its place and what to write instead, where glslang would say
// "'declaration' : Expected", "no matching overloaded function" or "unsupported construction".
// An intrinsic's name that the shader defines itself (a polyfill) is the shader's own.
void refuseUnsupportedFeatures(const std::vector<Token>& tokens);

} // namespace iblkit::lowering
