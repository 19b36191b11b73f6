#pragma once

#include "hlsl_tokens.hpp"

#include <vector>

namespace iblkit::lowering {

// HLSL 2021's select(c, a, b), and(a, b) and or(a, b) as the operators glslang applies
// component-wise: ((c) ? (a) : (b)), ((a) && (b)), ((a) || (b)). A shader that defines a
// function of one of these names keeps calling its own.
std::vector<Token> lowerIntrinsics(const std::vector<Token>& tokens);

} // namespace iblkit::lowering
