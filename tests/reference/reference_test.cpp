// The C++ reference's building blocks.
#include "cube_environment.hpp"
#include "pbr.hpp"

#include <gtest/gtest.h>

namespace iblkit::reference {
namespace {

TEST(Reference, VanDerCorputMirrorsTheBitsAboutTheBinaryPoint) {
    EXPECT_EQ(VanDerCorput<double>(0), 0.0);
    EXPECT_EQ(VanDerCorput<double>(1), 0.5);
    EXPECT_EQ(VanDerCorput<double>(2), 0.25);
    EXPECT_EQ(VanDerCorput<double>(3), 0.75);
    EXPECT_EQ(VanDerCorput<double>(0x80000000u), 1.0 / 4294967296.0);
    EXPECT_EQ(Hammersley<float>(3, 4), glm::vec2(0.75f, 0.75f));
}

TEST(Reference, GgxSamplesAreUnitVectorsAroundTheNormal) {
    const glm::dvec3 normal = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
    for (double roughness : {0.0, 0.3, 1.0})
        for (uint32_t i = 0; i < 64; ++i) {
            const auto h = ImportanceSampleGGX<double>(Hammersley<double>(i, 64), normal, roughness);
            EXPECT_NEAR(glm::length(h), 1.0, 1e-12);
            EXPECT_GE(glm::dot(h, normal), -1e-12);
            if (roughness == 0.0) {
                EXPECT_LT(glm::length(h - normal), 1e-12) << "roughness 0 samples the normal";
            }
        }
    // Near the pole the frame switches its up vector; samples stay around the normal.
    const auto h = ImportanceSampleGGX<double>({0.3, 0.5}, glm::dvec3(0, 1, 0), 0.5);
    EXPECT_GT(h.y, 0.0);
}

TEST(Reference, CubeSamplingReturnsTexelsAtTheirCentersAndIsSeamless) {
    const auto environment = CubeEnvironment::testEnvironment(8);
    for (uint32_t face = 0; face < 6; ++face) {
        const glm::dvec3 sampled = environment.sample(cubeTexelDirection(face, 3, 5, 8));
        const size_t at = ((face * 8 + 5) * 8 + 3) * 4;
        EXPECT_NEAR(sampled.r, environment.texels()[at], 1e-6) << face;
    }
    // Across the edge between +X and +Z the filtered value is continuous.
    const glm::dvec3 onEdge = glm::normalize(glm::dvec3(1, 0.2, 1));
    const glm::dvec3 justX = environment.sample(onEdge + glm::dvec3(1e-9, 0, 0));
    const glm::dvec3 justZ = environment.sample(onEdge + glm::dvec3(0, 0, 1e-9));
    EXPECT_LT(glm::length(justX - justZ), 1e-6);
}

} // namespace
} // namespace iblkit::reference
