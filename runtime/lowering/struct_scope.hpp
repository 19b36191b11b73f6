#pragma once

#include "hlsl_tokens.hpp"

#include <vector>

namespace iblkit::lowering {

// What C++ lets a struct hold and glslang's HLSL frontend does not: a static member with its
// value (`static const int MaxItems = 16;`) and an enum. Each is moved out of `struct S` into a
// `namespace S` just before it, and every use of its name inside the struct becomes S::name, so
// that the namespace lowering names it S__name there and at every S::name outside; the struct
// keeps its other members in their order. Runs before the enums and namespaces are lowered.
std::vector<Token> hoistStructScopeDeclarations(const std::vector<Token>& tokens);

} // namespace iblkit::lowering
