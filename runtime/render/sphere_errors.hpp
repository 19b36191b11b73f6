#pragma once

#include "render/reference_render.hpp"
#include "render/sphere_grid.hpp"
#include "render/sphere_images.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::render {

// One sphere's material and how far the split sum is from the reference over its pixels, each
// pixel's error (split sum - reference) / max(reference, floor) in luminance.
struct SphereError {
    uint32_t row = 0, column = 0;
    std::string material; // the row's name
    float roughness = 0, metalness = 0, transmittance = 0;
    size_t pixels = 0;
    double meanRelativeError = 0;        // mean of |error|
    double maxRelativeError = 0;         // max of |error|
    double totalRelativeError = 0;       // the sphere's summed luminance against the reference's, signed
    double maxRelativeStandardError = 0; // the reference's own, so that noise can be told from error
    double meanRelativeStandardError = 0; // over the pixels: the noise's share of meanRelativeError is about 0.8 of it
};

// Per pixel: the signed relative error; 0 where no sphere covers it.
std::vector<double> relativeErrors(const SphereImage& reference, const SphereImage& splitSum, double floor);

std::vector<SphereError> sphereErrors(const SphereGrid& grid, const ReferenceImage& reference, const SphereImage& splitSum,
                                      uint32_t cellSize, double floor);

} // namespace iblkit::render
