#pragma once

#include "hlsl_tokens.hpp"

#include <vector>

namespace iblkit::lowering {

// NonUniformResourceIndex(i), which glslang's HLSL frontend lacks, becomes (i); the compiler
// then decorates the SPIR-V (spirv_non_uniform.hpp). A shader that defines a function of that
// name (a polyfill for an older compiler) keeps its own.
std::vector<Token> lowerNonUniformResourceIndex(const std::vector<Token>& tokens);

} // namespace iblkit::lowering
