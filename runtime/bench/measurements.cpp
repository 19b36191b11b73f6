#include "measurements.hpp"

#include <algorithm>
#include <cmath>

namespace iblkit::bench {

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const size_t middle = values.size() / 2;
    return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

double luminance(glm::dvec3 rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b; }

double relativeLuminanceError(glm::dvec3 actual, glm::dvec3 reference) {
    const double difference = std::abs(luminance(actual) - luminance(reference));
    if (difference == 0) return 0;
    if (!std::isfinite(difference)) return INFINITY;
    return difference / std::abs(luminance(reference));
}

std::span<const float> SourceCube::mip(uint32_t level) const {
    size_t offset = 0;
    for (uint32_t m = 0; m < level; ++m) offset += size_t(6) * (size >> m) * (size >> m) * 4;
    const size_t count = size_t(6) * (size >> level) * (size >> level) * 4;
    return std::span<const float>(allMips).subspan(offset, count);
}

} // namespace iblkit::bench
