#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace iblkit::shading {

// Which way a view ray crosses a dielectric's rough interface (outside index 1, inside eta):
// entering from outside, or leaving from inside.
enum class Crossing { Entering, Leaving };

// The share of the light a rough interface passes on along a view ray that crosses it: the
// integral over L on the far side of the split sum's BTDF (hlsl/Common/SplitSumMaterial.fxh's
// BtdfAsSplitSum: Walter's, Smith-Schlick k = r² / 2, Schlick's F on the outside's cosine) times
// |N·L|, times (eta_L / eta_V)² so that it counts energy rather than radiance (radiance is
// divided by eta² on the way in and multiplied by it on the way out; over a solid's two
// crossings the factors cancel). Smooth, it is 1 - F; rough, less, as G masks and as more of the
// lobe meets total internal reflection on the way out. ndotv is |N·V| on V's side.
double transmittedShare(double ndotv, double roughness, double eta, Crossing crossing);

// One facet's part of transmittedShare, in the interface's frame (outward normal +Z, V on the
// side `crossing` says): V refracted through the facet of normal h (+Z side), and its weight per
// unit of D(h) cos θ_h dω_h, |V·h| (1 - F) G / (|N·V| cos θ_h); a zero direction and weight
// where V meets the facet's back or is reflected totally. A path through a solid carries the
// product of its crossings' weights.
struct FacetRefraction {
    glm::dvec3 direction{0};
    double weight = 0;
};
FacetRefraction refractThroughFacet(const glm::dvec3& V, const glm::dvec3& h, double roughness, double eta, Crossing crossing);

// The table the shading reads: for each index of refraction of kTransmissionEtas a layer of
// size x size texel centres, N·V = (x + 0.5) / size across and roughness = (y + 0.5) / size down,
// RG = (entering, leaving) row by row, layer after layer.
inline constexpr uint32_t kTransmissionTableSize = 32;
inline constexpr std::array<float, 8> kTransmissionEtas{1.1f, 1.3f, 1.5f, 1.7f, 1.9f, 2.1f, 2.3f, 2.5f};
std::vector<float> transmissionTable(uint32_t size);

// A table laid out as transmissionTable's, `channels` floats a texel, each filled by
// fill(N·V, roughness, eta, texel) at its texel centre, rows shared among the threads.
std::vector<float> tablePerEta(uint32_t size, uint32_t channels,
                               const std::function<void(double ndotv, double roughness, double eta, float* texel)>& fill);

} // namespace iblkit::shading
