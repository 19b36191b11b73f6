#pragma once

#include <cstdint>
#include <vector>

namespace iblkit::shading {

// What a solid sphere of rough glass (index eta, outside 1) passes on to a view ray that meets it
// at cos θ = N·V, through its two crossings (shading/transmission_table.hpp's facets) along the
// chord between them, as one prefiltered lookup reads it:
//   - energy: the share of the light that comes out (what Fresnel, G and total internal
//     reflection at the way out leave; light reflected inside is lost, as the BSDF drops it);
//   - angle: the mean direction the view ray leaves along, as its angle from -V, turned towards
//     N in the plane of N and V (the smooth sphere's refraction where the glass is smooth);
//   - roughness: the prefilter kernel (G1) whose tangent variance is the mean of the exiting
//     directions' two about that direction, 1 where they spread wider.
struct SphereTransmission {
    float energy = 0, angle = 0, roughness = 0;
};
// By quasi-Monte Carlo over `paths` pairs of facets drawn by D cos θ_h.
SphereTransmission sphereTransmission(double ndotv, double roughness, double eta, uint32_t paths);

// The table the glass shading reads, laid out as shading::transmissionTable's (one layer per
// index of kTransmissionEtas, N·V across, roughness down), RGBA = (energy, angle, roughness, 0).
inline constexpr uint32_t kSphereTransmissionPaths = 4096;
std::vector<float> sphereTransmissionTable(uint32_t size);

} // namespace iblkit::shading
