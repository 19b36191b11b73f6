#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace iblkit::render {

// An RGBA32F image of the sphere grid, rows top first; alpha is 1 where a sphere covers the pixel.
struct SphereImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;
    bool covered(size_t pixel) const { return rgba[4 * pixel + 3] > 0.5f; }
};

double luminance(std::span<const float> rgb);

// A value's luminance against the floor it is never measured below (kRelativeFloor).
double relativeTo(double value, double floor);

} // namespace iblkit::render
