#include "prefilter_sample_table.hpp"

#include <cmath>
#include <numbers>

namespace iblkit::reference {
namespace {

double radicalInverse(uint32_t bits) {
    double inverse = 0, digit = 0.5;
    for (; bits; bits >>= 1, digit *= 0.5)
        if (bits & 1u) inverse += digit;
    return inverse;
}

double distributionGgx(double ndoth, double roughness) {
    const double a2 = std::pow(roughness, 4), denominator = ndoth * ndoth * (a2 - 1) + 1;
    return a2 / (std::numbers::pi * denominator * denominator);
}

} // namespace

double filteredSourceLod(double ndoth, double roughness, uint32_t samples, uint32_t sourceSize) {
    const double d = distributionGgx(ndoth, roughness);
    if (!(d > 0) || std::isinf(d)) return kMirrorLod;
    const double texelSolidAngle = 4.0 / (double(sourceSize) * sourceSize);
    return 0.5 * std::log2(4.0 / (samples * d * texelSolidAngle));
}

std::vector<glm::vec4> prefilterSampleTable(double roughness, uint32_t samples, uint32_t sourceSize) {
    std::vector<glm::vec4> table;
    const double a2 = std::pow(roughness, 4);
    for (uint32_t i = 0; i < samples; ++i) {
        const double phi = 2 * std::numbers::pi * double(i) / samples, y = radicalInverse(i);
        const double cosTheta = std::sqrt((1 - y) / (1 + (a2 - 1) * y)), sinTheta = std::sqrt(1 - cosTheta * cosTheta);
        // L = 2 (V·H) H - V with V = N = +Z.
        const double ndotl = 2 * cosTheta * cosTheta - 1;
        if (!(ndotl > 0)) continue;
        const double scale = 2 * cosTheta * sinTheta;
        table.emplace_back(float(scale * std::cos(phi)), float(scale * std::sin(phi)), float(ndotl),
                           float(filteredSourceLod(cosTheta, roughness, samples, sourceSize)));
    }
    return table;
}

} // namespace iblkit::reference
