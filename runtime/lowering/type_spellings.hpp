#pragma once

#include "hlsl_tokens.hpp"

#include <vector>

namespace iblkit::lowering {

// Type spellings DXC and fxc take that glslang's HLSL frontend does not, written as the ones it
// does: `vector<half, 2>` as half2 and `matrix<min16float, 3, 3>` as min16float3x3 (glslang's
// templates take only float, int, uint, bool and double), and C's `unsigned int` and `unsigned`
// as uint; a minimum-precision matrix (min16float3x3, which glslang lacks) as half3x3; a swizzled
// literal (1.xxxx) as (1.0).xxxx.
std::vector<Token> lowerTypeSpellings(const std::vector<Token>& tokens);

} // namespace iblkit::lowering
