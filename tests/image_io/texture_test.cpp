// makeTexture and textureValues: the GPU layout (mip, face, row, column, channel), halves
// rounded to nearest even, infinities beyond the half range, and shapes no file can hold.
#include "image_io_test_support.hpp"
#include "texture.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

namespace iblkit::image_io {
namespace {

using testing::imageErrorOf;

std::vector<float> throughHalf(std::vector<float> values) {
    return textureValues(makeTexture(PixelFormat::Rg16Float, 1, uint32_t(values.size() / 2), 1, 1, values));
}

TEST(ImageIoTexture, FormatsDescribeTheirTexels) {
    EXPECT_EQ(bytesPerTexel(PixelFormat::Rgba16Float), 8u);
    EXPECT_EQ(bytesPerTexel(PixelFormat::Rgba32Float), 16u);
    EXPECT_EQ(bytesPerTexel(PixelFormat::Rg16Float), 4u);
    EXPECT_EQ(bytesPerTexel(PixelFormat::Rg32Float), 8u);
    EXPECT_EQ(channelCount(PixelFormat::Rg32Float), 2u);
    EXPECT_EQ(bytesPerChannel(PixelFormat::Rgba16Float), 2u);
    EXPECT_EQ(vulkanFormatName(PixelFormat::Rgba16Float), "R16G16B16A16_SFLOAT");
    EXPECT_EQ(vulkanFormatName(PixelFormat::Rgba32Float), "R32G32B32A32_SFLOAT");
    EXPECT_EQ(vulkanFormatName(PixelFormat::Rg16Float), "R16G16_SFLOAT");
    EXPECT_EQ(vulkanFormatName(PixelFormat::Rg32Float), "R32G32_SFLOAT");
}

TEST(ImageIoTexture, MipSizesHalveDownToOne) {
    const auto texture = makeTexture(PixelFormat::Rgba16Float, 5, 3, 1, 3, std::vector<float>((15 + 2 + 1) * 4));
    EXPECT_EQ(texture.mipWidth(1), 2u);
    EXPECT_EQ(texture.mipHeight(1), 1u);
    EXPECT_EQ(texture.mipWidth(2), 1u);
    EXPECT_EQ(texture.mipHeight(2), 1u);
    EXPECT_EQ(texture.faceBytes(0), 5u * 3 * 8);
    ASSERT_EQ(texture.levels.size(), 3u);
    EXPECT_EQ(texture.levels[1].size(), 2u * 8);
}

TEST(ImageIoTexture, LevelsHoldFacesThenRowsThenColumnsThenChannels) {
    // Value = 1000 * face + 100 * row + 10 * column + channel, in a 2x2 cube of one mip.
    std::vector<float> values;
    for (int face = 0; face < 6; ++face)
        for (int row = 0; row < 2; ++row)
            for (int column = 0; column < 2; ++column)
                for (int channel = 0; channel < 2; ++channel) values.push_back(float(1000 * face + 100 * row + 10 * column + channel));
    const auto texture = makeTexture(PixelFormat::Rg32Float, 2, 2, 6, 1, values);
    const auto at = [&](int face, int row, int column, int channel) {
        float value;
        std::memcpy(&value, texture.levels[0].data() + texture.faceBytes(0) * face + (row * 2 + column) * 8 + channel * 4, 4);
        return value;
    };
    EXPECT_EQ(at(4, 1, 0, 1), 4101.f);
    EXPECT_EQ(at(5, 0, 1, 0), 5010.f);
    EXPECT_EQ(textureValues(texture), values);
}

// 3003 lies halfway between the halves 3002 and 3004: round-to-nearest-even gives 3004 (even
// significand), rounding toward zero would give 3002. 3001 ties between 3000 (even) and 3002.
TEST(ImageIoTexture, HalvesRoundToNearestEven) {
    EXPECT_EQ(throughHalf({3003.f, 3001.f, 3003.5f, 3002.9f}), (std::vector<float>{3004.f, 3000.f, 3004.f, 3002.f}));
    const float tieBelowEven = 1.f + std::ldexp(1.f, -11), tieBelowOdd = 1.f + 3 * std::ldexp(1.f, -11);
    EXPECT_EQ(throughHalf({tieBelowEven, tieBelowOdd}), (std::vector<float>{1.f, 1.f + std::ldexp(1.f, -9)}));
}

TEST(ImageIoTexture, ValuesBeyondHalfRangeBecomeInfinities) {
    const float inf = std::numeric_limits<float>::infinity();
    // 65520 is halfway between the largest half, 65504, and the next step, 65536, which overflows.
    const auto values = throughHalf({65504.f, 65519.f, 65520.f, 1e6f, -1e6f, std::ldexp(1.f, -24), std::ldexp(1.f, -26), -65504.f});
    EXPECT_EQ(values, (std::vector<float>{65504.f, 65504.f, inf, inf, -inf, std::ldexp(1.f, -24), 0.f, -65504.f}));
    EXPECT_TRUE(std::isnan(throughHalf({std::nanf(""), 0.f})[0]));
}

TEST(ImageIoTexture, FloatsAreStoredBitForBit) {
    const std::vector<float> values = {-0.f, std::numeric_limits<float>::denorm_min(), 1e38f, -3.25f,
                                       std::numeric_limits<float>::infinity(), 0.1f, 7.f, 1e-30f};
    const auto back = textureValues(makeTexture(PixelFormat::Rgba32Float, 2, 1, 1, 1, values));
    ASSERT_EQ(back.size(), values.size());
    for (size_t i = 0; i < values.size(); ++i) EXPECT_EQ(std::bit_cast<uint32_t>(back[i]), std::bit_cast<uint32_t>(values[i])) << i;
}

TEST(ImageIoTexture, RefusesValueCountsThatDoNotMatchTheShape) {
    EXPECT_NE(imageErrorOf([] { makeTexture(PixelFormat::Rgba16Float, 2, 2, 1, 1, std::vector<float>(15)); }).find("15 values given; the texture holds 16"),
              std::string::npos);
    EXPECT_NE(imageErrorOf([] { makeTexture(PixelFormat::Rgba16Float, 2, 2, 1, 2, std::vector<float>(16)); }).find("holds 20"),
              std::string::npos);
}

TEST(ImageIoTexture, RefusesShapesNoFileCanHold) {
    const auto problem = [](uint32_t width, uint32_t height, uint32_t faces, uint32_t mips) {
        return imageErrorOf([&] { makeTexture(PixelFormat::Rg16Float, width, height, faces, mips, {}); });
    };
    EXPECT_NE(problem(0, 4, 1, 1).find("width or height of 0"), std::string::npos);
    EXPECT_NE(problem(4, 4, 3, 1).find("3 faces"), std::string::npos);
    EXPECT_NE(problem(8, 4, 6, 1).find("not square"), std::string::npos);
    EXPECT_NE(problem(8, 4, 1, 5).find("at most 4"), std::string::npos);
    EXPECT_NE(problem(8, 4, 1, 0).find("0 mips"), std::string::npos);
    EXPECT_NE(problem(70000, 1, 1, 1).find("larger than 65536"), std::string::npos);
}

} // namespace
} // namespace iblkit::image_io
