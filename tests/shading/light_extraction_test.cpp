// Lights taken out of an environment: one light per small bright region, across face edges, its
// light exactly what the residual lost, and nothing taken that is too wide, too dim or too many.
#include "shading/light_extraction.hpp"

#include "reference/cube_geometry.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace iblkit::shading {
namespace {

constexpr uint32_t kSize = 32;
constexpr double kDegree = std::numbers::pi / 180;

struct Disk {
    glm::dvec3 direction;
    double radius;
    float radiance;
};

// A sky of luminance 1 with disks of constant radiance, by texel centre.
std::vector<float> environment(const std::vector<Disk>& disks) {
    std::vector<float> faces(size_t(6) * kSize * kSize * 4, 1.f);
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t y = 0; y < kSize; ++y)
            for (uint32_t x = 0; x < kSize; ++x) {
                const auto d = reference::CubeFaceDirection<double>(face, glm::dvec2((x + 0.5) / kSize, (y + 0.5) / kSize));
                for (const auto& disk : disks)
                    if (std::acos(std::clamp(glm::dot(d, glm::normalize(disk.direction)), -1.0, 1.0)) < disk.radius)
                        for (int c = 0; c < 3; ++c) faces[((size_t(face) * kSize + y) * kSize + x) * 4 + c] = disk.radiance;
            }
    return faces;
}

double lightOf(const std::vector<float>& faces) {
    double total = 0;
    for (size_t texel = 0; texel < faces.size() / 4; ++texel) {
        const double luminance = 0.2126 * faces[4 * texel] + 0.7152 * faces[4 * texel + 1] + 0.0722 * faces[4 * texel + 2];
        total += luminance * reference::CubeTexelSolidAngle<double>(texel % kSize, texel / kSize % kSize, kSize);
    }
    return total;
}

double luminanceTimesSolidAngle(const EnvironmentLight& light) {
    return (0.2126 * light.radiance.r + 0.7152 * light.radiance.g + 0.0722 * light.radiance.b) * light.solidAngle;
}

TEST(LightExtraction, ASmallSunBecomesOneLightAndTheResidualKeepsTheRest) {
    const Disk sun{{0.3, 0.5, 0.8}, 4 * kDegree, 2000.f};
    const auto faces = environment({sun});
    const auto extraction = extractLights(faces, kSize, {});
    ASSERT_EQ(extraction.lights.size(), 1u);
    const auto& light = extraction.lights[0];
    EXPECT_LT(std::acos(glm::dot(light.direction, glm::normalize(sun.direction))), 1 * kDegree);
    // The residual and the light hold the environment's light, to rounding.
    EXPECT_NEAR(lightOf(extraction.residual) + luminanceTimesSolidAngle(light), lightOf(faces), 1e-9 * lightOf(faces));
    EXPECT_NEAR(light.share, luminanceTimesSolidAngle(light) / lightOf(faces), 1e-12);
    EXPECT_NEAR(light.share, 0.7, 0.03) << "a disk of 4 degrees 2000 times the sky: 0.0153 sr of 1999 against 4π of 1";
    // The sun's texels now hold the sky around them.
    for (size_t texel = 0; texel < faces.size() / 4; ++texel) EXPECT_NEAR(extraction.residual[4 * texel], 1.f, 1e-6) << texel;
    EXPECT_NEAR(light.angularRadius, sun.radius, 1.5 * kDegree);
    EXPECT_NEAR(light.radiance.g, sun.radiance - 1, 1e-9 * sun.radiance)
        << "the sun's light above the sky, over the disk of its texels' solid angle";
}

TEST(LightExtraction, ListsEveryTexelItChangedInOrderWithWhatItTookOut) {
    const auto faces = environment({{{0.3, 0.5, 0.8}, 4 * kDegree, 2000.f}, {{-0.7, 0.1, -0.4}, 3 * kDegree, 3000.f}});
    const auto extraction = extractLights(faces, kSize, {});
    ASSERT_EQ(extraction.lights.size(), 2u);
    size_t listed = 0;
    for (size_t texel = 0; texel < faces.size() / 4; ++texel) {
        const glm::vec3 before(faces[4 * texel], faces[4 * texel + 1], faces[4 * texel + 2]);
        const glm::vec3 after(extraction.residual[4 * texel], extraction.residual[4 * texel + 1], extraction.residual[4 * texel + 2]);
        if (before == after) continue;
        ASSERT_LT(listed, extraction.taken.size()) << texel;
        EXPECT_EQ(extraction.taken[listed].texel, texel);
        EXPECT_EQ(extraction.taken[listed].taken, before - after) << texel;
        ++listed;
    }
    EXPECT_EQ(listed, extraction.taken.size()) << "a listed texel the residual did not change";
    EXPECT_GE(listed, 8u) << "two suns of 4 and 3 degrees on 32² faces, of 2.8-degree texels: about 6 and 4 texels";
}

TEST(LightExtraction, ASunAcrossAFaceEdgeIsOneLight) {
    const Disk sun{{1.0, 0.1, 1.0}, 5 * kDegree, 2000.f}; // on the edge of +X and +Z
    const auto extraction = extractLights(environment({sun}), kSize, {});
    ASSERT_EQ(extraction.lights.size(), 1u);
    EXPECT_LT(std::acos(glm::dot(extraction.lights[0].direction, glm::normalize(sun.direction))), 1 * kDegree);
}

TEST(LightExtraction, TooWideTooDimOrTooManyIsLeftInTheMaps) {
    const ExtractionSettings settings{50, 0.02, 10 * kDegree, 2};
    EXPECT_TRUE(extractLights(environment({{{0, 1, 0}, 25 * kDegree, 2000.f}}), kSize, settings).lights.empty()) << "too wide";
    EXPECT_TRUE(extractLights(environment({{{0, 1, 0}, 5 * kDegree, 20.f}}), kSize, settings).lights.empty()) << "too dim";
    const auto three = extractLights(environment({{{1, 0.2, 0.3}, 4 * kDegree, 3000.f},
                                                  {{-1, 0.2, 0.3}, 6 * kDegree, 3000.f},
                                                  {{0.2, 0.3, -1}, 5 * kDegree, 3000.f}}),
                                     kSize, settings);
    ASSERT_EQ(three.lights.size(), 2u) << "too many";
    EXPECT_GT(three.lights[0].share, three.lights[1].share);
    EXPECT_LT(three.lights[0].direction.x, 0) << "the widest, and brightest in all, first";
}

TEST(LightExtraction, AnEnvironmentOfZerosHasNoLight) {
    const std::vector<float> faces(size_t(6) * kSize * kSize * 4, 0.f);
    const auto extraction = extractLights(faces, kSize, {});
    EXPECT_TRUE(extraction.lights.empty());
    EXPECT_EQ(extraction.residual, faces);
}

} // namespace
} // namespace iblkit::shading
