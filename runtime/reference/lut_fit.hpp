#pragma once

#include <glm/vec2.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::reference {

// The polynomial LUT: (scale, bias) as Σ c_ab T_a(2u - 1) T_b(2w - 1), a, b = 0..degree, with
// u = N·V^(1/4), w = roughness^(1/2) (the roots spread the turn of Schlick-GGX's G1 near N·V = 0
// at low roughness over more of the domain; cube roots fit about as well, but llvmpipe's pow took
// a third of the dispatch where a square root is one instruction) and T the Chebyshev
// polynomials, clamped to [0, 1]. Fitted by least squares, in double, to the converged LUT at kLutFitNodes² points
// uniform in (u, w), both ends included.
inline constexpr uint32_t kMaxLutFitDegree = 9;
inline constexpr uint32_t kLutFitNodes = 96;

// The (degree + 1)² coefficients, a-major. Throws std::invalid_argument for a degree of 0 or
// above kMaxLutFitDegree.
std::vector<glm::dvec2> fitBrdfLut(uint32_t degree);
// Every degree's, 1 to kMaxLutFitDegree, from one evaluation of the converged LUT (a few seconds).
std::vector<std::vector<glm::dvec2>> fitBrdfLutEveryDegree();

// The polynomial at one (N·V, roughness), following BrdfLutFitCS's arithmetic in T.
template <typename T>
glm::vec<2, T> evaluateBrdfLutFit(T ndotv, T roughness, const std::vector<glm::vec<2, T>>& coefficients);

// BrdfLutFitCS over a size² LUT (texel centres, laid out as PrecomputedBrdfCS's), (scale, bias)
// per texel, row by row.
template <typename T>
std::vector<T> brdfLutFromFit(uint32_t size, const std::vector<glm::vec<2, T>>& coefficients);

// hlsl/Common/BrdfLutFit.fxh: every degree's coefficients, in float, as BrdfLutFitCS reads them.
std::string brdfLutFitInclude();

} // namespace iblkit::reference
