#include "pyramid_ring.hpp"

#include "pbr.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <vector>

namespace iblkit::reference {
namespace {

constexpr int kAngleSteps = 4096;

// The lobe's mass within each step's upper angle, by the midpoint rule over θ in [0, π/2]:
// D(cos(θ / 2)) cos θ sin θ dθ, H halfway between N = V and L.
std::vector<double> cumulativeMass(double roughness) {
    std::vector<double> mass(kAngleSteps + 1, 0.0);
    const double step = std::numbers::pi / 2 / kAngleSteps;
    for (int i = 1; i <= kAngleSteps; ++i) {
        const double theta = (i - 0.5) * step;
        mass[i] = mass[i - 1] + DistributionGGX(std::cos(theta / 2), roughness) * std::cos(theta) * std::sin(theta);
    }
    return mass;
}

// The angle within which `fraction` of `mass` (cumulativeMass's) lies, linear within a step.
double quantileAngle(const std::vector<double>& mass, double fraction) {
    const double wanted = fraction * mass.back();
    const auto above = std::lower_bound(mass.begin(), mass.end(), wanted);
    if (above == mass.begin()) return 0;
    const auto at = size_t(above - mass.begin());
    const double within = (wanted - mass[at - 1]) / (mass[at] - mass[at - 1]);
    return (double(at - 1) + within) * std::numbers::pi / 2 / kAngleSteps;
}

} // namespace

double lobeQuantileAngle(double roughness, double fraction) { return quantileAngle(cumulativeMass(roughness), fraction); }

std::optional<PyramidRing> pyramidRing(double roughness, uint32_t sourceSize) {
    const auto mass = cumulativeMass(roughness);
    const double capAngle = quantileAngle(mass, 0.5);
    if (capAngle < std::numbers::pi / 8) return std::nullopt;
    const double ringAngle = quantileAngle(mass, 0.75);
    const double texel = 2.0 / sourceSize; // a mip-0 texel's width at a face centre
    const double top = std::bit_width(sourceSize) - 1;
    const double spacing = 2 * std::numbers::pi * std::sin(ringAngle) / kPyramidRingReads;
    const auto lod = [&](double width) { return float(std::clamp(std::log2(width / texel), 0.0, top)); };
    return PyramidRing{float(std::min(double(lod(capAngle)) + 0.5, top)), lod(spacing), float(std::cos(ringAngle)), 0.5f};
}

} // namespace iblkit::reference
