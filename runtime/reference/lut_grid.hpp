#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace iblkit::reference {

// The quadrature-grid LUT in C++, function by function as hlsl/BrdfLutGridCS.hlsl and
// hlsl/BrdfLutResampleCS.hlsl compute it (Common/LutGrid.fxh): T = float follows the shaders'
// arithmetic, T = double shows what the method itself is worth.

// (scale, bias) at the nodes of a gridSize² grid, N.V = u³ and roughness = w³ with u, w =
// i / (gridSize - 1), row by row, by IntegrateBrdfQuadrature at `nodes` per panel.
template <typename T>
std::vector<T> brdfLutGridNodes(uint32_t gridSize, uint32_t nodes);

// A size² LUT (N.V = (x + 0.5) / size across, roughness = (y + 0.5) / size down) by bicubic
// Catmull-Rom interpolation of `grid` in the grid's coordinates, the end intervals completed by
// quadratic extrapolation. gridSize is at least 4.
template <typename T>
std::vector<T> resampleBrdfLutGrid(std::span<const T> grid, uint32_t gridSize, uint32_t size);

} // namespace iblkit::reference
