#pragma once

#include "hlsl_tokens.hpp"

#include <string>
#include <vector>

namespace iblkit::lowering {

// DXC's explicit 16-bit types under glslang's names: float16_t[N[xM]] is half, int16_t[N] is
// min16int, uint16_t[N] is min16uint (16 bits wide once glslang's 16-bit types are on). Without
// `enabled` they are refused as DXC refuses them, naming -enable-16bit-types. Every min16* type
// seen without it adds one warning: the kit compiles it at 32 bits.
std::vector<Token> lowerSixteenBitTypes(const std::vector<Token>& tokens, bool enabled, std::vector<std::string>& warnings);

} // namespace iblkit::lowering
