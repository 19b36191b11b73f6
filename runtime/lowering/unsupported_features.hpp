#pragma once

#include "hlsl_tokens.hpp"

#include <string>
#include <vector>

namespace iblkit::lowering {

// Features of DXC's HLSL that glslang's HLSL frontend does not have and no lowering gives it:
// interfaces, ray tracing, Shader Model 6.6 dynamic resources, int64_t and 64-bit vectors,
// literals converted to uint64_t, and the Shader Model 6.4-6.6 intrinsics it lacks (dot2add,
// dot4add_*, pack_* and unpack_*, WaveMatch, WaveMultiPrefix*). A LoweringError names the first
// literal converted to uint64_t, else the first other one, with its place and what to write
// instead, where glslang would say "'declaration' : Expected", "no matching overloaded function"
// or "unsupported construction". An intrinsic the shader defines as a function of its own (a
// polyfill for older compilers) is the shader's own; a type name never is.
void refuseUnsupportedFeatures(const std::vector<Token>& tokens);

// Whether `name` is one of those features (a type, an intrinsic or a keyword glslang lacks).
bool glslangLacks(const std::string& name);

} // namespace iblkit::lowering
