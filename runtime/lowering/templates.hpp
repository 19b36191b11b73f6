#pragma once

#include "hlsl_tokens.hpp"

#include <vector>

namespace iblkit::lowering {

// HLSL 2021 templates and sizeof, which glslang's HLSL frontend lacks, lowered by instantiating
// them as a C++ compiler does:
// - a function template, called with its arguments written (twice<float>(x)) or deduced from the
//   call's arguments (twice(x), where each argument's type is declared or plain: a variable, a
//   parameter, a literal, a constructor or a cast), becomes one function per argument list
//   (twice__float), declared before the first declaration that calls it;
// - a struct template used with its arguments (Box<float3>) becomes one struct per list
//   (Box__float3);
// - template parameters are types (typename T, class T) or constants (uint N), and an instance
//   may use other templates, which are instantiated in turn;
// - sizeof(type) and sizeof(variable) become the size in bytes as DXC lays the type out in a
//   structured buffer (scalars of 4 bytes, or 2 and 8 for 16- and 64-bit ones, aligned to their
//   size; a struct's members in order, its size rounded to its widest scalar).
// What the kit cannot instantiate soundly (a default template argument, a specialization, a
// member template, arguments it cannot deduce) is refused by name, at its place, with what to
// write instead. Throws LoweringError.
std::vector<Token> lowerTemplates(const std::vector<Token>& tokens, bool sixteenBitTypes);

} // namespace iblkit::lowering
