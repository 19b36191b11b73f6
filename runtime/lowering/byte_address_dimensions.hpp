#pragma once

#include "hlsl_tokens.hpp"

#include <vector>

namespace iblkit::lowering {

// glslang's HLSL frontend answers a byte-address buffer's GetDimensions with the count of 32-bit
// words it holds (the length of the uint array it declares); Direct3D and DXC answer bytes, which
// is what shaders divide by their stride (and what SPIRV-Cross's HLSL form of a StructuredBuffer's
// length expects). The call, a statement of its own on a ByteAddressBuffer, RWByteAddressBuffer or
// RasterizerOrderedByteAddressBuffer declared before it, becomes a block that also makes its
// result bytes: { Data.GetDimensions(n); n *= 4u; }.
std::vector<Token> scaleByteAddressDimensions(const std::vector<Token>& tokens);

} // namespace iblkit::lowering
