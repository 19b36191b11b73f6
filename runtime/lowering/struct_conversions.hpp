#pragma once

#include "hlsl_tokens.hpp"

#include <vector>

namespace iblkit::lowering {

// A struct returned where another struct of the same member types is the return type
// (`Interpolants main(Vertex input) { return input; }`), which HLSL converts member by member
// and glslang refuses, written as that conversion: a value of the return type, each member
// assigned from the member at its place, returned. Done for a returned parameter or local whose
// declared type is a struct with the return type's member types in order.
std::vector<Token> convertReturnedStructs(const std::vector<Token>& tokens);

} // namespace iblkit::lowering
