// A light's diffuse: the cosine integral of a spherical cap, its horizon's clipping included.
#include "shading/disk_light.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace iblkit::shading {
namespace {

constexpr double kPi = std::numbers::pi;

// ∫ max(0, n·l) dω over the cap by a fine polar grid about its axis (midpoint rule in the
// angle from the axis and in azimuth), n at angle θ from the axis.
double numericCapCosine(double theta, double sigma) {
    const glm::dvec3 n(std::sin(theta), 0, std::cos(theta));
    const int rings = 2000, sectors = 2000;
    double sum = 0;
    for (int i = 0; i < rings; ++i) {
        const double a = (i + 0.5) / rings * sigma, da = sigma / rings;
        for (int j = 0; j < sectors; ++j) {
            const double phi = (j + 0.5) / sectors * 2 * kPi;
            const glm::dvec3 l(std::sin(a) * std::cos(phi), std::sin(a) * std::sin(phi), std::cos(a));
            sum += std::max(0.0, glm::dot(n, l)) * std::sin(a) * da * (2 * kPi / sectors);
        }
    }
    return sum;
}

TEST(CapCosine, AboveTheHorizonItIsTheProjectedDiskBelowItNothing) {
    const double sigma = 0.05, s2 = std::sin(sigma) * std::sin(sigma);
    for (const double theta : {0.0, 0.5, 1.2, 1.5})
        EXPECT_NEAR(capCosine(std::cos(theta), s2), kPi * s2 * std::cos(theta), 1e-15) << theta;
    EXPECT_EQ(capCosine(std::cos(kPi / 2 + 0.06), s2), 0.0);
    EXPECT_EQ(capCosine(-1, s2), 0.0);
    EXPECT_EQ(capCosine(0, 0), 0.0) << "a light of no size";
}

// Where the horizon cuts the cap: against the numeric integral, relative to the cap's full
// cosine weight π sin²σ (the midpoint rule at 2000² is good to about 1e-6 of it).
TEST(CapCosine, WhereTheHorizonCutsTheCapItCountsThePartAboveIt) {
    for (const double sigma : {0.01, 0.05, 0.1})
        for (const double offset : {-0.9, -0.5, 0.0, 0.5, 0.9}) {
            const double theta = kPi / 2 + offset * sigma, s2 = std::sin(sigma) * std::sin(sigma);
            EXPECT_NEAR(capCosine(std::cos(theta), s2), numericCapCosine(theta, sigma), 1e-5 * kPi * s2)
                << "σ " << sigma << ", centre " << offset << " σ below the horizon";
        }
}

TEST(CapCosine, ALightsIrradianceIsItsRadianceTimesTheCapsCosineOverPi) {
    EnvironmentLight light;
    light.direction = {0, 0, 1};
    light.radiance = {2, 3, 4};
    light.angularRadius = 0.02;
    light.solidAngle = 2 * kPi * (1 - std::cos(light.angularRadius));
    const auto e = diskIrradianceOverPi(light, glm::dvec3(0, 0, 1));
    // Head on, π sin²σ = Ω (1 + cos σ) / 2: the cap's solid angle, very nearly.
    EXPECT_NEAR(e.b, 4 * light.solidAngle * (1 + std::cos(light.angularRadius)) / 2 / kPi, 1e-15);
}

} // namespace
} // namespace iblkit::shading
