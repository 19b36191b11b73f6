// The heat map of render's error.png: each pixel's colour from its signed relative error, black
// off the spheres, and the legend's scale under the image.
#include "render/heat_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

namespace iblkit::render {
namespace {

using Rgba = std::array<int, 4>;

Rgba pixel(const Rgba8Image& image, uint32_t x, uint32_t y) {
    const auto* texel = &image.rgba[4 * (size_t(y) * image.width + x)];
    return {texel[0], texel[1], texel[2], texel[3]};
}

// The scale's ends: blue where the split sum is darker, red where
// it is brighter, each 255 * the colour of colourOf (0.23, 0.30, 0.75) and (0.71, 0.02, 0.15).
constexpr Rgba kWhite{255, 255, 255, 255}, kBlack{0, 0, 0, 255}, kDarkest{59, 77, 191, 255}, kBrightest{181, 5, 38, 255};

TEST(HeatMap, EachPixelTakesTheColourOfItsError) {
    const std::vector<double> errors{0.0, -kHeatMapRange, kHeatMapRange, -4 * kHeatMapRange, 9 * kHeatMapRange, 0.0};
    const std::vector<bool> covered{true, true, true, true, true, false};
    const auto image = heatMap(errors, covered, 6, 1);
    EXPECT_EQ(pixel(image, 0, 0), kWhite);
    EXPECT_EQ(pixel(image, 1, 0), kDarkest);
    EXPECT_EQ(pixel(image, 2, 0), kBrightest);
    EXPECT_EQ(pixel(image, 3, 0), kDarkest) << "errors past the range show at its end";
    EXPECT_EQ(pixel(image, 4, 0), kBrightest);
    EXPECT_EQ(pixel(image, 5, 0), kBlack) << "off the spheres";
}

TEST(HeatMap, HalfTheRangeIsHalfwayToTheEnd) {
    const auto image = heatMap({kHeatMapRange / 2, -kHeatMapRange / 2}, {true, true}, 2, 1);
    EXPECT_EQ(pixel(image, 0, 0), (Rgba{218, 130, 147, 255})); // white mixed halfway to (181, 5, 38)
    EXPECT_EQ(pixel(image, 1, 0), (Rgba{157, 166, 223, 255}));
}

TEST(HeatMap, TheLegendRunsFromDarkerToBrighterUnderTheImage) {
    const uint32_t width = 200, height = 10;
    const auto image = heatMap(std::vector<double>(width * height, 0.0), std::vector<bool>(width * height, true), width, height);
    ASSERT_EQ(image.width, width);
    ASSERT_GT(image.height, height);
    ASSERT_EQ(image.rgba.size(), size_t(4) * image.width * image.height);
    // The bar's first row: the first under the image with colour a little in from the left end.
    uint32_t bar = height;
    while (bar < image.height && pixel(image, 17, bar) == kBlack) ++bar;
    ASSERT_LT(bar, image.height) << "no legend bar under the image";
    const auto left = pixel(image, 17, bar), right = pixel(image, width - 18, bar);
    EXPECT_GT(left[2], left[0]) << "the left end is blue";
    EXPECT_GT(right[0], right[2]) << "the right end is red";
    const auto middle = pixel(image, width / 2, bar);
    EXPECT_GE(std::min({middle[0], middle[1], middle[2]}), 250) << "no error is white";
    EXPECT_EQ(pixel(image, 0, bar), kBlack) << "the margin";
}

} // namespace
} // namespace iblkit::render
