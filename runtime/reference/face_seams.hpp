#pragma once

#include "converged_prefilter.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace iblkit::reference {

// Texels facing each other across the cube's 12 edges: `perEdge` evenly spaced along each edge
// of each face, with the texel the extrapolated direction reaches on the neighbouring face; each
// pair once (from the face of lower index).
std::vector<std::array<PrefilterTexel, 2>> faceEdgePairs(uint32_t size, uint32_t perEdge);

// The largest relative jump of luminance across the pairs, |L_a - L_b| / ((L_a + L_b) / 2);
// `radiance[i]` is the radiance of pair i / 2's texel i % 2. 0 where both are black.
double largestSeamJump(const std::vector<glm::dvec3>& radiance);

} // namespace iblkit::reference
