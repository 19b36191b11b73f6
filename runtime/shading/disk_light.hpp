#pragma once

#include "shading/light_extraction.hpp"

#include <glm/vec3.hpp>

namespace iblkit::shading {

// ∫ max(0, n·l) dω over a uniform spherical cap of angular radius σ whose centre lies at
// cos θ from n, the horizon's clipping included (Snyder 1996; Lagarde and de Rousiers 2014,
// Frostbite's illuminanceSphereOrDisk): π sin²σ cos θ while the cap is above the horizon, 0
// once it is below, and between the closed form of the clipped cap. Common/ImageBasedLighting.fxh's
// IblCapCosine in double.
double capCosine(double cosTheta, double sinSigmaSquared);

// E(n) / π of the light on a surface of normal n, as IblDiskLight adds it: its radiance times
// capCosine of the cap of its solid angle, over π.
glm::dvec3 diskIrradianceOverPi(const EnvironmentLight& light, const glm::dvec3& normal);

} // namespace iblkit::shading
