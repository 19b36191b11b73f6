#pragma once

#include "hlsl_tokens.hpp"

#include <vector>

namespace iblkit::lowering {

// A local variable that holds a resource (`ByteAddressBuffer vertices = Buffers[i];`), which
// glslang's HLSL frontend refuses ("buffer aliasing not yet supported"), is replaced by what it
// was initialized with at each of its uses, to the end of its block: the resource the variable
// names. Done only when nothing the initializer reads is assigned later in that block, so that
// every use names the same resource the variable held; otherwise glslang's refusal stands. A value
// that holds a feature glslang lacks (ResourceDescriptorHeap[i]) is left for its refusal by name.
std::vector<Token> inlineResourceLocals(const std::vector<Token>& tokens);

} // namespace iblkit::lowering
