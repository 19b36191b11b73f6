#include "render/sphere_images.hpp"

#include <algorithm>

namespace iblkit::render {

double luminance(std::span<const float> rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

double relativeTo(double value, double floor) { return std::max(value, floor); }

} // namespace iblkit::render
