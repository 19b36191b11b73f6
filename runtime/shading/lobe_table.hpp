#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace iblkit::shading {

// How the prefilter weighs the lobe about N = V (hlsl/PrefilterConvolutionCS.hlsl's LobeWeighting):
// by N·L, as the documents' PrefilterSpecular does, or by Smith-Schlick's G1(N·L) with k = r² / 2,
// the split sum's own G at N = V (G1(N·V) = 1 there). At roughness 1, D is constant and the
// reflected lobe f (N·L) is proportional to G1(N·L) whatever V is: N·L weighs it 23 % too much
// head on and 36 % too little at N·L = 0.05.
enum class LobeWeighting { NdotL, G1 };
// "N·L" or "G1", as the manifest and the reports name it.
std::string_view nameOf(LobeWeighting weighting);

// The prefilter's kernel about its direction d at roughness r, per unit solid angle of L:
// D(sqrt((1 + d·L) / 2)) times the weighting of d·L, 0 below d's horizon.
double prefilterKernel(double cosine, double roughness, LobeWeighting weighting);

// The kernel's spread: E[sin² θ] / 2, the variance of L along one tangent axis of d.
double kernelTangentVariance(double roughness, LobeWeighting weighting);

// The roughness whose kernel has tangent variance `variance`: the inverse of
// kernelTangentVariance, 1 where the variance is past roughness 1's.
class KernelRoughness {
public:
    explicit KernelRoughness(LobeWeighting weighting);
    double roughnessFor(double variance) const;

private:
    std::vector<double> variances_; // at roughness (i + 1) / kSteps
};

// What one prefiltered lookup reads of the split sum's reflection lobe at (N·V, roughness), and
// how two lookups share it, from the lobe's moments (the split sum's BSDF without F:
// D(N·H) G1(N·L) G1(N·V) / (4 N·V), Smith-Schlick k = r² / 2):
//   - blend: the lobe's mean direction, as the share of the angle from N to R where it lies
//     (1 at R; at grazing views rough lobes lean towards N);
//   - roughness: the kernel whose tangent variance is the lobe's mean of its two about that
//     direction (one lookup);
//   - pairRoughness, pairSpread: two lookups at ± pairSpread radians about the mean direction in
//     the plane of N and V, each of the kernel whose variance is the lobe's across that plane:
//     together they have the lobe's variance along it too, where a grazing lobe is long.
struct LobeFit {
    float blend = 1, roughness = 0, pairRoughness = 0, pairSpread = 0;
};

LobeFit fitLobe(double ndotv, double roughness, LobeWeighting weighting);

// fitLobe over size x size texel centres, N·V = (x + 0.5) / size across and roughness =
// (y + 0.5) / size down, RGBA (blend, roughness, pairRoughness, pairSpread) row by row: the table
// the shading reads with a linear sampler at (N·V, roughness), as it reads the BRDF LUT.
inline constexpr uint32_t kLobeTableSize = 32;
std::vector<float> lobeTable(uint32_t size, LobeWeighting weighting);

} // namespace iblkit::shading
