// The sphere transmission fit against what it must be where it is known: smooth, it is the
// smooth sphere's refraction (Schlick's 1 - F twice, along the ray bent at both crossings); head
// on, the lobe is centred on -V; rough, less comes out and it spreads, but less than a reflection
// would (a refracted ray turns by a fraction of its facet's tilt, a reflected one by twice it).
#include "shading/sphere_transmission.hpp"

#include "shading/transmission_table.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace iblkit::shading {
namespace {

constexpr double kEta = 1.5;

double schlickTransmission(double cosine) {
    const double f0 = std::pow((1 - kEta) / (1 + kEta), 2);
    return 1 - (f0 + (1 - f0) * std::pow(1 - cosine, 5));
}

// The smooth sphere's exiting direction's angle from -V towards N.
double smoothAngle(double ndotv) {
    const glm::dvec3 N(0, 0, 1), V(std::sqrt(1 - ndotv * ndotv), 0, ndotv);
    const glm::dvec3 inside = glm::refract(-V, N, 1 / kEta);
    const glm::dvec3 exitPoint = N - 2 * glm::dot(N, inside) * inside;
    const glm::dvec3 outside = glm::refract(inside, -exitPoint, kEta);
    const glm::dvec3 u = glm::normalize(N - ndotv * V);
    return std::atan2(glm::dot(outside, u), glm::dot(outside, -V));
}

TEST(SphereTransmission, SmoothItIsTheSmoothSpheresRefraction) {
    for (const double ndotv : {0.3, 0.6, 0.9}) {
        const auto fit = sphereTransmission(ndotv, 0.01, kEta, kSphereTransmissionPaths);
        // The way out meets the surface at the way in's angle: Schlick's F at N·V both times.
        // Within 1e-3 at roughness 0.01 (its facets' tilt of 1e-4 radians).
        EXPECT_NEAR(fit.energy, std::pow(schlickTransmission(ndotv), 2), 1e-3) << ndotv;
        EXPECT_NEAR(fit.angle, smoothAngle(ndotv), 1e-3) << ndotv;
        EXPECT_LT(fit.roughness, 0.03) << ndotv;
    }
}

TEST(SphereTransmission, HeadOnTheLobeIsCentredBehind) {
    // Within the mean's quasi-Monte Carlo noise: 1.7e-3 radians at roughness 1 (0.1°, of a lobe
    // whose spread is about 0.5 radians), less below.
    for (const double roughness : {0.2, 0.6, 1.0})
        EXPECT_NEAR(sphereTransmission(1.0, roughness, kEta, kSphereTransmissionPaths).angle, 0.0, 2.5e-3) << roughness;
}

TEST(SphereTransmission, RougherPassesLessAndSpreadsWiderThanSmoothButLessThanAReflection) {
    double previousEnergy = 2, previousRoughness = 0;
    for (const double roughness : {0.1, 0.3, 0.5, 0.7, 1.0}) {
        const auto fit = sphereTransmission(0.8, roughness, kEta, kSphereTransmissionPaths);
        EXPECT_LT(fit.energy, previousEnergy) << roughness;
        EXPECT_GT(fit.roughness, previousRoughness) << roughness;
        EXPECT_LT(fit.roughness, roughness) << roughness;
        previousEnergy = fit.energy, previousRoughness = fit.roughness;
    }
}

TEST(SphereTransmission, TheTableHoldsTheFitsAtItsTexelCentresLayerByLayer) {
    const uint32_t size = 2;
    const auto table = sphereTransmissionTable(size);
    ASSERT_EQ(table.size(), size_t(size) * size * kTransmissionEtas.size() * 4);
    const size_t layer = 2, x = 1, y = 0; // eta 1.5, N·V 0.75, roughness 0.25
    const float* texel = &table[((layer * size + y) * size + x) * 4];
    const auto fit = sphereTransmission(0.75, 0.25, 1.5, kSphereTransmissionPaths);
    EXPECT_FLOAT_EQ(texel[0], fit.energy);
    EXPECT_FLOAT_EQ(texel[1], fit.angle);
    EXPECT_FLOAT_EQ(texel[2], fit.roughness);
}

} // namespace
} // namespace iblkit::shading
