#pragma once

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace iblkit::reference {

// Gauss–Legendre nodes per panel of the deterministic quadrature below. The panels are graded
// geometrically towards every near-singularity (the N·L = 0 edge of the visible arc, where
// Schlick-GGX turns on over a width k = roughness² / 2), so these counts need not grow as
// roughness or N·V shrink: 16 by 16 is converged to about 1e-13 everywhere (see
// tests/reference/converged_lut_test.cpp), and doubling both is the self-convergence check.
struct LutQuadrature {
    uint32_t thetaNodes = 16; // along the half-vector's polar angle
    uint32_t phiNodes = 16;   // along its azimuth
};

// The split-sum integrals that IntegrateBRDF estimates, at one (N·V, roughness):
//   scale = ∫_{N·L>0} (1 - Fc) · G(N·L, N·V) · V·H / (N·H · N·V) · D(H)·N·H dω_h,  bias the same with Fc,
//   Fc = (1 - V·H)^5, D = GGX with α = roughness², G = the document's GemoetrySmithForIBL
//   (Schlick-GGX, k = roughness² / 2).
// Arguments are clamped to [0, 1]. Roughness 0 returns the mirror limit (1 - (1 - N·V)^5, (1 - N·V)^5);
// N·V = 0 is finite for roughness > 0 (G(N·V) / N·V → 1 / k).
glm::dvec2 convergedBrdf(double ndotv, double roughness, const LutQuadrature& quadrature = {});

// Over a size x size grid laid out like PrecomputedBrdfCS (column x: N·V = (x + 0.5) / size,
// row y: roughness = (y + 0.5) / size): (scale, bias) per texel, row by row, on every hardware thread.
std::vector<double> convergedBrdfLut(uint32_t size, const LutQuadrature& quadrature = {});

} // namespace iblkit::reference
