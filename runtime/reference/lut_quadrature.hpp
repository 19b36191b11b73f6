#pragma once

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace iblkit::reference {

// hlsl/Common/BrdfQuadrature.fxh (BrdfLutQuadratureCS's functions) in C++, function by function (the same names, constants and
// order of operations): T = float follows the shader's arithmetic, T = double shows what the
// method itself is worth. (scale, bias) at one (N.V, roughness) with `nodes` Gauss–Legendre
// nodes per panel (1 to 16); N.V in [0, 1] and 1 - N.V, given apart for its precision near N.V = 1.
template <typename T>
glm::vec<2, T> IntegrateBrdfQuadrature(T ndotv, T ndotvComplement, T roughness, uint32_t nodes);

// Over a size x size grid laid out like BrdfLutQuadratureCS (column x: N.V = (x + 0.5) / size,
// row y: roughness = (y + 0.5) / size): (scale, bias) per texel, row by row.
template <typename T>
std::vector<T> brdfLutQuadrature(uint32_t size, uint32_t nodes);

} // namespace iblkit::reference
