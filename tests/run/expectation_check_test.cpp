#include "expectation_check.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace iblkit::run {
namespace {

const auto& half = vulkan::texelFormatNamed("R16G16_SFLOAT");
const auto& single = vulkan::texelFormatNamed("R32_SFLOAT");
const auto& unorm = vulkan::texelFormatNamed("R8G8B8A8_UNORM");

TEST(UlpDistance, CountsRepresentableStepsOfTheFormat) {
    EXPECT_EQ(ulpDistance(half, 1.0, 1.0 + 1.0 / 1024), 1.0);   // a half's step at 1 is 2^-10
    EXPECT_EQ(ulpDistance(half, 2048.0, 2052.0), 2.0);          // and 2 at 2048
    EXPECT_EQ(ulpDistance(single, 1.0, std::nextafter(1.0f, 2.0f)), 1.0);
    EXPECT_EQ(ulpDistance(single, -0.0, 0.0), 0.0);
    EXPECT_EQ(ulpDistance(single, -std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::denorm_min()), 2.0);
    EXPECT_EQ(ulpDistance(unorm, 0.5, 0.5 + 1.0 / 255), 1.0);
    EXPECT_TRUE(std::isinf(ulpDistance(single, NAN, 1.0)));
}

TEST(CompareValues, ExactUnlessAToleranceIsGiven) {
    const std::vector<double> actual = {1.0f, 2.0f, 3.001f};
    const std::vector<double> expected = {1.0, 2.0, 3.0};
    EXPECT_FALSE(compareValues(actual, expected, {}, single).passed);
    EXPECT_TRUE(compareValues(actual, expected, {0.002, {}, {}}, single).passed);
    EXPECT_FALSE(compareValues(actual, expected, {0.0005, {}, {}}, single).passed);
    EXPECT_TRUE(compareValues(actual, expected, {{}, 0.001, {}}, single).passed);
    EXPECT_FALSE(compareValues(actual, expected, {{}, {}, 100.0}, single).passed);
}

TEST(CompareValues, ReportsTheWorstFailingValue) {
    const std::vector<double> actual = {1.5f, 2.0f, 3.2f, 4.0f};
    const std::vector<double> expected = {1.0, 2.0, 3.0, 4.0};
    const auto result = compareValues(actual, expected, {0.3, {}, {}}, single);
    EXPECT_FALSE(result.passed);
    EXPECT_EQ(result.failed, 1u);
    EXPECT_EQ(result.worstIndex, 0u);
    EXPECT_DOUBLE_EQ(result.worstAbsolute, 0.5);
}

TEST(CompareValues, NanMatchesOnlyNan) {
    EXPECT_TRUE(compareValues(std::vector<double>{NAN}, std::vector<double>{NAN}, {}, single).passed);
    EXPECT_FALSE(compareValues(std::vector<double>{NAN}, std::vector<double>{1.0}, {1e9, {}, {}}, single).passed);
    EXPECT_FALSE(compareValues(std::vector<double>{1.0f}, std::vector<double>{NAN}, {1e9, {}, {}}, single).passed);
}

TEST(CheckRange, InfinitiesAndNansAreOutside) {
    EXPECT_TRUE(checkRange(std::vector<double>{0.0f, 1.0f, 0.5f}, 0, 1).passed);
    EXPECT_FALSE(checkRange(std::vector<double>{0.0f, INFINITY}, 0, 1e30).passed);
    EXPECT_FALSE(checkRange(std::vector<double>{NAN}, -1e30, 1e30).passed);
    const auto result = checkRange(std::vector<double>{0.25f, -0.5f, 0.75f}, 0, 1);
    EXPECT_EQ(result.failed, 1u);
    EXPECT_EQ(result.minimum, -0.5);
    EXPECT_EQ(result.maximum, 0.75);
}

} // namespace
} // namespace iblkit::run
