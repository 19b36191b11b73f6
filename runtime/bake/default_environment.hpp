#pragma once

#include "float_image.hpp"

#include <glm/vec3.hpp>

#include <cstdint>

namespace iblkit::bake {

// The built-in environment: a blue sky brightening to a hazy horizon, a sun disc of 2.5° radius
// and radiance 4000 with a glow (about six times the sky's irradiance, like a clear day), and a
// checkered ground, so mirror spheres show sharp structure and rough ones its blur.
glm::dvec3 defaultEnvironmentRadiance(glm::dvec3 direction);

// defaultEnvironmentRadiance as an equirectangular panorama of width x width / 2 (RGB), in the
// kit's panorama convention (hlsl/Common/Cube.fxh), each texel the mean of 2x2 subsamples.
image_io::FloatImage defaultEnvironmentPanorama(uint32_t width);

} // namespace iblkit::bake
