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

void ErrorSummary::add(double error) {
    sumSquares_ += error * error;
    max_ = std::max(max_, std::isnan(error) ? INFINITY : error);
    ++count_;
}

double ErrorSummary::rms() const { return count_ ? std::sqrt(sumSquares_ / double(count_)) : 0; }

std::vector<double> flatten(const std::vector<glm::dvec3>& rgb) {
    std::vector<double> values;
    values.reserve(rgb.size() * 3);
    for (const auto& value : rgb) values.insert(values.end(), {value.r, value.g, value.b});
    return values;
}

std::vector<glm::dvec3> unflatten(const std::vector<double>& values) {
    std::vector<glm::dvec3> rgb(values.size() / 3);
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
    return rgb;
}

double luminance(glm::dvec3 rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b; }

double relativeLuminanceError(glm::dvec3 actual, glm::dvec3 reference) {
    const double difference = std::abs(luminance(actual) - luminance(reference));
    if (difference == 0) return 0;
    if (!std::isfinite(difference)) return INFINITY;
    return difference / std::abs(luminance(reference));
}

} // namespace iblkit::bench
