#pragma once

#include "hlsl_tokens.hpp"

#include <vector>

namespace iblkit::lowering {

// HLSL 2021 constructs the lowering cannot express for glslang: templates, operator
// overloading, bitfields, sizeof and an enum inside a struct. The first one found is a
// LoweringError that names it and its place.
void refuseUnlowerable(const std::vector<Token>& tokens);

} // namespace iblkit::lowering
