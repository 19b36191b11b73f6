#pragma once

#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace iblkit::reference {

// The lod that filtered importance sampling reads a sample at (Křivánek & Colbert 2008): the
// mip of a sourceSize cube whose texels at a face centre, (2 / sourceSize)² sr at mip 0 and 4
// times more per mip, cover the solid angle the sample stands for, 1 / (samples pdf(L)). At
// N = V, pdf(L) = D(N·H) / 4. Not clamped; a D that is 0 or not a number (a lobe too narrow to
// represent: roughness 0) gives kMirrorLod.
double filteredSourceLod(double ndoth, double roughness, uint32_t samples, uint32_t sourceSize);
inline constexpr double kMirrorLod = -64; // below mip 0 wherever on the cube the sample falls

// The sample-table prefilter's host half (Filament's cmgen builds its tables so): the
// document's GGX samples (Hammersley points through ImportanceSampleGGX's inverse CDF) at
// N = V = +Z, computed once per roughness in double and shared by every texel. Each entry is
// (L.x, L.y, L.z, lod): L in the frame of the texel's normal, its z = N·L the sample's weight,
// and its filteredSourceLod. Samples below the horizon are left out, in order.
std::vector<glm::vec4> prefilterSampleTable(double roughness, uint32_t samples, uint32_t sourceSize);

} // namespace iblkit::reference
