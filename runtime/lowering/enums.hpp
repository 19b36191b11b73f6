#pragma once

#include "hlsl_tokens.hpp"

#include <vector>

namespace iblkit::lowering {

// HLSL 2021 enums as glslang's HLSL has them: `enum [class] E [: T] { A, B = 4 }` becomes
// `typedef T E;` (int when T is not given) and one `static const E ... = value;` per
// enumerator, where it stood. An unscoped enumerator keeps its name, a scoped one is E__A;
// `E::A` names it either way. Casts to and from E are casts to and from T.
std::vector<Token> lowerEnums(const std::vector<Token>& tokens);

// The name a scoped enumerator gets.
std::string scopedEnumeratorName(const std::string& enumName, const std::string& enumerator);

} // namespace iblkit::lowering
