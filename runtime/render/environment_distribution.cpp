#include "environment_distribution.hpp"

#include "reference/cube_geometry.hpp"
#include "render/sphere_images.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace iblkit::render {

std::vector<float> environmentCdf(std::span<const float> faces, uint32_t faceSize) {
    const size_t texels = size_t(6) * faceSize * faceSize;
    if (faces.size() != texels * 4) throw std::invalid_argument("environmentCdf: faces and faceSize disagree");
    std::vector<double> solidAngle(texels), weight(texels);
    double weightSum = 0;
    for (size_t i = 0; i < texels; ++i) {
        const auto column = uint32_t(i % faceSize), row = uint32_t(i / faceSize % faceSize);
        solidAngle[i] = reference::CubeTexelSolidAngle<double>(column, row, faceSize);
        weight[i] = std::max(luminance(faces.subspan(4 * i, 4)), 0.0) * solidAngle[i];
        weightSum += weight[i];
    }
    const double lit = weightSum > 0 && std::isfinite(weightSum) ? 1.0 - kUniformShare : 0.0;
    constexpr double kSteps = 16777216.0; // 2^24
    std::vector<float> cdf(texels);
    double cumulative = 0, previousStep = 0;
    for (size_t i = 0; i < texels; ++i) {
        const double spread = lit > 0 ? weight[i] / weightSum : 0.0;
        cumulative += lit * spread + (1.0 - lit) * solidAngle[i] / (4.0 * std::numbers::pi);
        const double texelsLeft = double(texels - 1 - i);
        const double step = std::clamp(std::round(cumulative * kSteps), previousStep + 1, kSteps - texelsLeft);
        cdf[i] = float(step / kSteps);
        previousStep = step;
    }
    return cdf;
}

} // namespace iblkit::render
