// The distribution RenderReferenceCS draws environment directions from: a CDF on the 2^-24 grid
// Random() draws on, in proportion to luminance times solid angle, with a uniform share.
#include "render/environment_distribution.hpp"

#include "reference/cube_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace iblkit::render {
namespace {

constexpr uint32_t kSize = 8;
constexpr double kStep = 1.0 / 16777216.0;

std::vector<float> constantFaces(float value) { return std::vector<float>(6 * kSize * kSize * 4, value); }

double probabilityOf(const std::vector<float>& cdf, size_t i) { return double(cdf[i]) - (i ? double(cdf[i - 1]) : 0.0); }

TEST(EnvironmentDistribution, IsACdfOnTheDrawsGrid) {
    auto faces = constantFaces(0.5f);
    faces[4 * 77] = 1e5f; // a sun's red channel
    const auto cdf = environmentCdf(faces, kSize);
    ASSERT_EQ(cdf.size(), 6u * kSize * kSize);
    EXPECT_EQ(cdf.back(), 1.f);
    for (size_t i = 0; i < cdf.size(); ++i) {
        EXPECT_GT(probabilityOf(cdf, i), 0.0) << "texel " << i << " could never be drawn";
        EXPECT_EQ(std::fmod(double(cdf[i]) / kStep, 1.0), 0.0) << "texel " << i << " is off the 2^-24 grid";
    }
}

TEST(EnvironmentDistribution, FollowsLuminanceTimesSolidAngleWithAUniformShare) {
    auto faces = constantFaces(0.f);
    const size_t sun = 77;
    for (int c = 0; c < 3; ++c) faces[4 * sun + c] = 1000.f;
    const auto cdf = environmentCdf(faces, kSize);
    const double sunSolidAngle = reference::CubeTexelSolidAngle<double>(sun % kSize, sun / kSize % kSize, kSize);
    const double expected = (1 - kUniformShare) + kUniformShare * sunSolidAngle / (4 * std::numbers::pi);
    // Rounding to the grid moves each entry by half a step at most.
    EXPECT_NEAR(probabilityOf(cdf, sun), expected, kStep);
    const double other = reference::CubeTexelSolidAngle<double>(0, 0, kSize) * kUniformShare / (4 * std::numbers::pi);
    EXPECT_NEAR(probabilityOf(cdf, 0), other, kStep);
}

TEST(EnvironmentDistribution, TwoLitTexelsOfOtherColoursAndSolidAnglesShareByLuminanceTimesSolidAngle) {
    auto faces = constantFaces(0.f);
    const size_t corner = 0, centre = 2 * kSize * kSize + kSize / 2 * kSize + kSize / 2; // face +Y's corner and centre
    const float red[3] = {900.f, 0.f, 0.f}, blue[3] = {0.f, 0.f, 2500.f};
    for (int c = 0; c < 3; ++c) faces[4 * corner + c] = red[c], faces[4 * centre + c] = blue[c];
    const auto cdf = environmentCdf(faces, kSize);
    const double cornerLight = 0.2126 * 900 * reference::CubeTexelSolidAngle<double>(0, 0, kSize);
    const double centreLight = 0.0722 * 2500 * reference::CubeTexelSolidAngle<double>(kSize / 2, kSize / 2, kSize);
    const double lit = 1 - kUniformShare, total = cornerLight + centreLight;
    const auto uniform = [&](size_t texel) {
        return kUniformShare * reference::CubeTexelSolidAngle<double>(texel % kSize, texel / kSize % kSize, kSize) /
               (4 * std::numbers::pi);
    };
    // Each within the grid's rounding: 0.20 and 0.70 of the draws (of the lit 0.9), the corner's
    // texel a quarter of the centre's solid angle, its luminance (red's weight against blue's)
    // 1.06 times as much.
    EXPECT_NEAR(probabilityOf(cdf, corner), lit * cornerLight / total + uniform(corner), kStep);
    EXPECT_NEAR(probabilityOf(cdf, centre), lit * centreLight / total + uniform(centre), kStep);
}

TEST(EnvironmentDistribution, ABlackEnvironmentIsSpreadBySolidAngle) {
    const auto cdf = environmentCdf(constantFaces(0.f), kSize);
    const double corner = reference::CubeTexelSolidAngle<double>(0, 0, kSize) / (4 * std::numbers::pi);
    const double centre = reference::CubeTexelSolidAngle<double>(kSize / 2, kSize / 2, kSize) / (4 * std::numbers::pi);
    EXPECT_NEAR(probabilityOf(cdf, 0), corner, kStep);
    EXPECT_NEAR(probabilityOf(cdf, kSize / 2 * kSize + kSize / 2), centre, kStep);
    EXPECT_EQ(cdf.back(), 1.f);
}

TEST(EnvironmentDistribution, RefusesFacesOfAnotherSize) {
    EXPECT_THROW(environmentCdf(constantFaces(1.f), kSize * 2), std::invalid_argument);
}

} // namespace
} // namespace iblkit::render
