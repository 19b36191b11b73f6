#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace iblkit::shading {

// A small bright source taken out of an environment: a disk of constant radiance about
// `direction`, of the solid angle its texels covered, carrying exactly the light they held above
// what surrounds them.
struct EnvironmentLight {
    glm::dvec3 direction{0, 0, 1}; // unit, towards the light
    glm::dvec3 radiance{0};
    double solidAngle = 0;
    double angularRadius = 0; // of the disk of that solid angle
    double share = 0;         // of the environment's light (luminance times solid angle)
};

// Which sources become lights: the connected regions of texels brighter than `threshold` times
// the environment's mean luminance, each carrying at least `minShare` of its light within
// `maxRadius` radians (as a disk of the region's solid angle); the `maxLights` largest shares.
struct ExtractionSettings {
    double threshold = 50;
    double minShare = 0.02;
    double maxRadius = 0.1;
    uint32_t maxLights = 8;
};

// A texel the extraction changed: its index in the faces (face, row, column) and the radiance taken
// out of it, its value less the residual's.
struct TakenTexel {
    size_t texel = 0;
    glm::vec3 taken{0};
};

struct Extraction {
    std::vector<EnvironmentLight> lights;
    std::vector<float> residual; // the faces with each light's texels filled in from their surroundings
    std::vector<TakenTexel> taken; // by texel index, every texel whose residual differs from the faces
};

// `faces`: RGBA floats, face +X..-Z, row, column, size x size each (the bake's source cube, mip 0).
// Each light's texels take their surroundings' values, grown inwards from the region's edge a
// ring at a time (the mean of the neighbours already known), never above their own value; the
// light is what that leaves, so the residual plus the lights hold the environment's light
// exactly.
// The residual is `faces` itself, changed in place: move a cube in to spare its copy.
Extraction extractLights(std::vector<float> faces, uint32_t size, const ExtractionSettings& settings);

} // namespace iblkit::shading
