#pragma once

#include "hlsl_tokens.hpp"

#include <vector>

namespace iblkit::lowering {

// HLSL 2021 namespaces flattened into names: what `namespace N { ... }` declares at its own
// scope (functions, structs, typedefs, constants, resources, cbuffer members, nested
// namespaces) is renamed N__name at its declaration and at every use, whether written N::name,
// or name inside N. `::name` is the global name. A local variable or parameter hides a
// namespace member of the same name, as in C++. `using namespace` and namespace aliases are
// refused; `using Name = type;` becomes a typedef.
std::vector<Token> lowerNamespaces(const std::vector<Token>& tokens);

} // namespace iblkit::lowering
