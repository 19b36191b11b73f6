#pragma once

#include "hlsl_tokens.hpp"

#include <string>
#include <vector>

namespace iblkit::lowering {

// Drops the top-level declarations that the entry point never reaches (through any name it or
// what it reaches uses) and that are functions, or hold a feature glslang's HLSL frontend lacks:
// the other passes' helpers of an engine's shared header, a ray tracing acceleration structure it
// declares for them. DXC emits only what the entry point reaches, and so does the kit; a feature
// the entry point does reach is still refused by name. Unused resources that glslang can express
// stay, as they are (the reflection lists them). Nothing is dropped when the entry point is not
// defined at the top level.
std::vector<Token> dropUnreachableUnsupported(const std::vector<Token>& tokens, const std::string& entryPoint);

} // namespace iblkit::lowering
