#include "shading/disk_light.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace iblkit::shading {

double capCosine(double cosTheta, double sinSigmaSquared) {
    constexpr double kPi = std::numbers::pi;
    if (cosTheta * cosTheta > sinSigmaSquared || sinSigmaSquared <= 0) return kPi * sinSigmaSquared * std::max(cosTheta, 0.0);
    const double sinTheta = std::sqrt(std::max(1 - cosTheta * cosTheta, 0.0));
    const double x = std::sqrt(1 / sinSigmaSquared - 1);
    const double y = -x * (cosTheta / sinTheta);
    const double sinThetaSqrtY = sinTheta * std::sqrt(std::max(1 - y * y, 0.0));
    return std::max((cosTheta * std::acos(std::clamp(y, -1.0, 1.0)) - x * sinThetaSqrtY) * sinSigmaSquared +
                        std::atan(sinThetaSqrtY / x),
                    0.0);
}

glm::dvec3 diskIrradianceOverPi(const EnvironmentLight& light, const glm::dvec3& normal) {
    const double sinSigma = std::sin(light.angularRadius);
    return light.radiance * (capCosine(glm::dot(normal, light.direction), sinSigma * sinSigma) / std::numbers::pi);
}

} // namespace iblkit::shading
