#pragma once

#include "hlsl_tokens.hpp"

#include <vector>

namespace iblkit::lowering {

// DXR's plain structs, RayDesc and BuiltInTriangleIntersectionAttributes, which glslang's HLSL
// frontend lacks, declared as the HLSL specification defines them where a shader uses one
// without declaring it: code that builds rays outside ray tracing (a compute pass setting up a
// primary ray) compiles as DXC compiles it. Tracing the ray is still refused by name.
std::vector<Token> declareBuiltinStructs(const std::vector<Token>& tokens);

} // namespace iblkit::lowering
