#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>

namespace iblkit::reference {

// A cube face as a plane: the unnormalised direction at face coordinates (a, b) in [-1, 1]² is
// origin + a·u + b·v (cubeTexelDirection's table), and dω = da db / (1 + a² + b²)^{3/2}.
struct FacePlane {
    glm::dvec3 origin, u, v;
};
FacePlane facePlane(uint32_t face);

// The lobe that PrefilterSpecular's samples follow for N = V: L = reflect(-N, H) with H ~ D·N·H
// has pdf D·N·H / (4 V·H) = D / 4, and each sample is weighted by N·L, so the estimate tends to
// ∫ c(L) D(N·H(L)) N·L dω / ∫ D(N·H(L)) N·L dω over N·L > 0. With N·H² = (1 + N·L) / 2,
//   D = α² / (π (N·H² (α² - 1) + 1)²) = 4α² / (π ((1 - N·L) + α² (1 + N·L))²);
// weight() is D·N·L times πα² / 4 (the factor cancels in the ratio), at most 1/4. With
// `g1Weighting`, N·L becomes Smith-Schlick's G1(N·L) = N·L / (N·L (1 - k) + k), k = α / 2
// (PrefilterConvolutionCS's Weighting 1, the split sum's own lobe at N = V).
class PrefilterLobe {
public:
    PrefilterLobe(glm::dvec3 normal, double alpha, uint32_t supersampling, bool g1Weighting = false);

    // ∫ weight dω over the square [a0, a0 + side] x [b0, b0 + side] of `face`, N·L > 0 only:
    // tensor Gauss–Legendre on sub-squares refined (a quadtree) until each is small against the
    // lobe's scale there; the part beyond the horizon N·L = 0, a straight line in the face
    // plane, is cut away exactly.
    double overSquare(uint32_t face, double a0, double b0, double side) const;

    // The same by 2 x 2 Gauss–Legendre alone, for a square wholly above the horizon whose
    // centre is at least farCentreAngle from N.
    double overFarSquare(uint32_t face, double a0, double b0, double side) const;

    // The angle between N and a square's centre beyond which the 2 x 2 rule is converged on it
    // (the choice overSquare makes), for a square of angular size `size`: its side divided by
    // sqrt(1 + a² + b²) at its centre.
    static double farCentreAngle(double size, double alpha, uint32_t supersampling);

    double weight(double ndotl, double oneMinusNdotl) const {
        const double spread = oneMinusNdotl * inverseAlpha2_ + (1 + ndotl);
        const double lobe = g1K_ > 0 ? ndotl / (ndotl * (1 - g1K_) + g1K_) : ndotl;
        return lobe / (spread * spread);
    }

private:
    double overSquareAtDepth(uint32_t face, double a0, double b0, double side, uint32_t depth) const;
    double tensorRule(uint32_t face, double a0, double b0, double side, uint32_t order) const;
    double clippedRule(uint32_t face, double a0, double b0, double side, uint32_t order) const;
    double atNode(uint32_t face, double a, double b) const; // weight times the Jacobian
    double aboveHorizon(uint32_t face, double a, double b) const; // N·P, P unnormalised

    glm::dvec3 normal_;
    double alpha2_, inverseAlpha2_;
    double g1K_ = 0; // Smith-Schlick's k with G1's weighting, 0 with N·L's
    uint32_t supersampling_;
    std::array<FacePlane, 6> faces_;
    std::array<glm::dvec3, 6> normalOnFace_; // (N·origin, N·u, N·v)
};

} // namespace iblkit::reference
