// The built-in environment's cube: its supersampling keeps the sun's energy, and it is the
// environment it claims to be.
#include "read_file.hpp"
#include "sky_environment.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <stdexcept>

namespace iblkit::reference {
namespace {

// The radiance times solid angle of the whole cube, green channel (the sun's is 0.92 of its red).
double cubeEnergy(const std::vector<double>& texels, uint32_t size) {
    double energy = 0;
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x)
                energy += texels[((size_t(face) * size + y) * size + x) * 4 + 1] * CubeTexelSolidAngle<double>(x, y, size);
    return energy;
}

TEST(SkyEnvironment, FourByFourEvaluationsKeepTheSunsEnergy) {
    // At 64² the sun's disc is under 3 texels across, harder than the bake's 256² (11).
    const uint32_t size = 64;
    const double fine = cubeEnergy(skyCube<double>(size, 16), size);
    const double error = std::abs(cubeEnergy(skyCube<double>(size, 4), size) / fine - 1);
    const double single = std::abs(cubeEnergy(skyCube<double>(size, 1), size) / fine - 1);
    RecordProperty("energy_error_4x4", std::to_string(error));
    RecordProperty("energy_error_1x1", std::to_string(single));
    // Measured 1.9e-3 (1.5e-5 at 256²), bound twice that; one evaluation per texel is 2.9e-2 off,
    // so the supersampling is what keeps the sun.
    EXPECT_LT(error, 4e-3);
    EXPECT_GT(single, 1e-2);
}

// The sun's direction as SkyCubeCS.hlsl, the sky the bake renders, names it.
glm::dvec3 shadersSun() {
    const auto source = testing::readFile("hlsl/SkyCubeCS.hlsl");
    static const std::regex sun(R"(float3 sun = normalize\( float3\( ([-0-9.]+)f, ([-0-9.]+)f, ([-0-9.]+)f \) \))");
    std::smatch match;
    if (!std::regex_search(source, match, sun)) throw std::runtime_error("SkyCubeCS.hlsl names no sun direction");
    return glm::normalize(glm::dvec3(std::stod(match[1]), std::stod(match[2]), std::stod(match[3])));
}

// The C++ sky's brightest direction, found by search (a 0.25° grid, then 0.01° about the best), is
// the shader's sun; its glow falls off away from it, and the opposite side is dark.
TEST(SkyEnvironment, TheSunIsWhereTheSkyShaderPutsIt) {
    const auto brightest = [](double thetaFrom, double thetaTo, double phiFrom, double phiTo, double step) {
        glm::dvec3 best(0);
        double most = -1;
        for (double theta = thetaFrom; theta <= thetaTo; theta += step)
            for (double phi = phiFrom; phi <= phiTo; phi += step) {
                const glm::dvec3 direction(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
                if (const double r = EnvironmentRadiance(direction).r; r > most) most = r, best = direction;
            }
        return best;
    };
    const double degree = std::acos(-1.0) / 180;
    auto best = brightest(0, 180 * degree, -180 * degree, 180 * degree, 0.25 * degree);
    const double theta = std::acos(best.y), phi = std::atan2(best.z, best.x);
    best = brightest(theta - 0.5 * degree, theta + 0.5 * degree, phi - 0.5 * degree, phi + 0.5 * degree, 0.01 * degree);
    const auto sun = shadersSun();
    // Measured 0.0036° off: the search's own resolution, its last step being 0.01°. Two steps
    // bound it; a sun moved by the smallest change of a component in the shader's text (0.01, about
    // 0.6°) is far past it.
    EXPECT_LT(std::acos(std::min(1.0, glm::dot(best, sun))), 0.02 * degree) << "the C++ sky's sun is not the shader's";
    // Along a great circle away from the sun: dimmer at every step out to 20°.
    const glm::dvec3 across = glm::normalize(glm::cross(sun, glm::dvec3(0, 1, 0)));
    double previous = EnvironmentRadiance(sun).r;
    for (double angle = 1; angle <= 20; angle += 1) {
        const double r = EnvironmentRadiance(std::cos(angle * degree) * sun + std::sin(angle * degree) * across).r;
        EXPECT_LT(r, previous) << angle << "° from the sun";
        previous = r;
    }
    EXPECT_LT(EnvironmentRadiance(-sun).r, 1e-3 * EnvironmentRadiance(sun).r);
}

} // namespace
} // namespace iblkit::reference
