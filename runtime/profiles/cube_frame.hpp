#pragma once

#include "profiles/engine_profile.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>

namespace iblkit::profiles {

// The kit's direction whose radiance a file in `frame` holds at direction `fileDirection`.
glm::dvec3 kitDirectionOf(CubeFrame frame, glm::dvec3 fileDirection);

// Rearranges a cube's texels (order mip, face +X..-Z, row, column; `channels` floats each) from
// the kit's frame into `frame`, in place.
void arrangeCube(CubeFrame frame, std::span<float> values, uint32_t size, uint32_t mips, uint32_t channels);

} // namespace iblkit::profiles
