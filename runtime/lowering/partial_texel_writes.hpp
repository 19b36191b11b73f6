#pragma once

#include "hlsl_tokens.hpp"

#include <vector>

namespace iblkit::lowering {

// A write to some components of a storage texel (`Output[coords].rgb = color;`,
// `Data[i].w += 1;`), which glslang's HLSL frontend refuses ("partial image updates"), becomes
// what DXC compiles it to: the texel read, its components written, the texel stored back, in a
// block of its own with the coordinates evaluated once. Done for RWTexture*, RWBuffer and
// RasterizerOrdered* resources whose declaration precedes the write (a global, a parameter or a
// local), as a statement of its own; an index into an array of such resources must be free of
// side effects, since it is read twice.
std::vector<Token> lowerPartialTexelWrites(const std::vector<Token>& tokens);

// A storage resource's Load given coordinates of another length (`Image.Load(int3(xy, 0))` on a
// RWTexture2D, written as for a Texture2D), which DXC truncates with a warning and glslang finds
// ambiguous, converted to the resource's coordinates: Image.Load((int2)(int3(xy, 0))). Only
// Load with one argument, on resources declared as partial texel writes find them.
std::vector<Token> convertStorageLoadCoordinates(const std::vector<Token>& tokens);

} // namespace iblkit::lowering
