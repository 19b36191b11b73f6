#pragma once

#include "shading/light_extraction.hpp"

#include <string>
#include <vector>

namespace iblkit::bake {

// The lights a recipe took out of the environment as a glTF 2.0 file (lights.gltf): one
// KHR_lights_punctual directional light per source, on a node whose -Z, where the extension's
// light shines, runs from the source towards the scene. Directions are in the frame the maps are
// sampled in, the cube's (Common/Cube.fxh). A directional light has no size: its illuminance
// (radiance times solid angle, in the environment's units) is `intensity` times `color` (the
// largest channel 1), and each light's extras keep the disk: its radiance, angular radius and
// solid angle, and its share of the environment's light.
std::string lightsGltf(const std::vector<shading::EnvironmentLight>& lights, const std::string& generator);

} // namespace iblkit::bake
