#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace iblkit::reference {

struct PrefilterTexel {
    uint32_t face, x, y;
    bool operator==(const PrefilterTexel&) const = default;
};

// `count` distinct texels of a size x size cube face set, chosen by std::mt19937_64 seeded with
// `seed` (its raw output, so the choice is the same on every standard library), sorted by
// face, row, column; all of them when count >= 6 size².
std::vector<PrefilterTexel> seededPrefilterTexels(uint32_t size, uint32_t count, uint64_t seed);

struct ConvergedPrefilterOptions {
    uint32_t supersampling = 1; // multiplier on the adaptive sub-texel counts, for self-convergence tests
    bool g1Weighting = false;   // the lobe D·G1(N·L) (PrefilterConvolutionCS's Weighting 1) instead of D·N·L
};

// The converged prefiltered radiance (RGB) of a cube source (RGBA floats ordered face +X, -X,
// +Y, -Y, +Z, -Z, row, column; sourceSize x sourceSize faces) taken as piecewise constant over
// its texels, for each of `texels` of an outputSize cube (N = V = R =
// PrefilterFaceDirection<double>(face, x, y, outputSize)), at `roughness` (clamped to [0, 1]):
// the limit of PrefilterSpecular's ratio of sums,
//   P(N) = Σ_t c_t W_t / Σ_t W_t,  W_t = ∫_{texel t, N·L > 0} D(N·H(L)) N·L dω_L,  H = normalize(N + L),
// over every source texel. Below roughness 1e-5 (α < 1e-10, a lobe narrower than double
// precision resolves against a texel; it then differs from the mirror only by tails of relative
// weight O(α² / texel²)) it returns the mirror limit: the texel containing N, found as nearest
// filtering would (the face of N's largest component, +X before +Y before +Z on ties, then the
// texel its face coordinates fall in; on an edge between texels, the one with the larger
// column or row). Multithreaded over `texels`; each result is the RGB of the matching texel.
std::vector<glm::dvec3> convergedPrefilter(std::span<const float> sourceTexels, uint32_t sourceSize, double roughness,
                                          uint32_t outputSize, std::span<const PrefilterTexel> texels,
                                          const ConvergedPrefilterOptions& options = {});

} // namespace iblkit::reference
