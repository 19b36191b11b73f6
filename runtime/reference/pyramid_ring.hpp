#pragma once

#include <cstdint>
#include <optional>

namespace iblkit::reference {

// The pyramid method's reads for a lobe too wide for reads along the normal alone: one read
// along N for the half of the lobe's mass nearest it, and kPyramidRingReads reads evenly around
// a ring for the other half, at the angle from N that halves the outer half's mass (the lobe's
// 75 % quantile). The mass is the prefilter lobe's at N = V, D(N·H) N·L dω.
struct PyramidRing {
    float centreLod = 0;   // at a face centre: a texel half a level above the central cap's radius
    float ringLod = 0;     // a texel as wide as the ring's reads are apart
    float cosAngle = 0;    // of the ring's angle from N
    float centreWeight = 0; // the centre read's; the ring's reads share the rest
};

inline constexpr uint32_t kPyramidRingReads = 8;

// The angle from N within which `fraction` of the lobe's mass at `roughness` lies (0 to π/2).
double lobeQuantileAngle(double roughness, double fraction);

// The ring for `roughness` on a cube of sourceSize² faces, or nothing where half the lobe's mass
// lies within π/8 of N: there the reads along N (fitPyramidReads) are closer, and the ring's
// nine reads would cost most on the mips with the most texels. Lods are clamped to the chain.
std::optional<PyramidRing> pyramidRing(double roughness, uint32_t sourceSize);

} // namespace iblkit::reference
