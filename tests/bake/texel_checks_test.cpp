// The input and output texel checks: colour channels only (alpha carries no light), counts by
// texel, and the first offender where one is named.
#include "bake_outputs.hpp"
#include "texel_checks.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace iblkit::bake {
namespace {

TEST(TexelChecks, NegativeTexelsAreCountedOnceAndClampedInTheirColourChannels) {
    std::vector<float> rgba{1, -2e-4f, -1e-5f, -9, /**/ 0.5f, 0.5f, 0.5f, 1, /**/ -7.5e-4f, 2, 3, 0};
    const auto found = findNegativeTexels(rgba, 4);
    EXPECT_EQ(found.count, 2u) << "a texel with two negative channels counts once; alpha is not light";
    EXPECT_FLOAT_EQ(found.mostNegative, -7.5e-4f);
    clampNegativeToZero(rgba, 4);
    EXPECT_EQ(rgba, (std::vector<float>{1, 0, 0, -9, 0.5f, 0.5f, 0.5f, 1, 0, 2, 3, 0}));
    EXPECT_EQ(findNegativeTexels(rgba, 4).count, 0u);
}

TEST(TexelChecks, TheFirstTexelPastTheLargestRadianceIsNamed) {
    std::vector<float> rgb{1, 1, 1, 1e19f, 1e20f, 1, 2, 1, -1e21f, 1e37f, 1, 1};
    const auto found = findOversizedTexel(rgb, 3);
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(found->texel, 2u) << "1e20 itself is taken; -1e21 is past it";
    EXPECT_FLOAT_EQ(found->value, -1e21f);
    EXPECT_FALSE(findOversizedTexel(std::vector<float>{1e20f, 0, 0, 1e30f}, 4).has_value()) << "alpha is not light";
}

TEST(TexelChecks, AHalfRangeClampReportsTheWorstMipsShareOfEnergy) {
    // A 2x2 cube with one mip-1 level: mip 0 has one texel of 2 * 65504 among 23 of 1 per
    // channel; mip 1 is within range. The share is mip 0's, weighted by solid angle (all four
    // texels of a 2x2 face subtend the same angle, so it is the plain ratio).
    BakedTexture texture{"specular", image_io::PixelFormat::Rgba16Float, 2, 6, 2, std::vector<float>((24 + 6) * 4, 1.f)};
    for (int c = 0; c < 3; ++c) texture.values[c] = 2 * 65504.f;
    const auto clamp = applyHalfRangePolicy(texture, false);
    ASSERT_TRUE(clamp.has_value());
    EXPECT_EQ(clamp->values, 3u);
    EXPECT_EQ(clamp->worstMip, 0u);
    EXPECT_NEAR(clamp->worstShare, 65504.0 / (2 * 65504.0 + 23), 1e-12);
    EXPECT_EQ(texture.values[0], 65504.f);
    EXPECT_FALSE(applyHalfRangePolicy(texture, false).has_value()) << "nothing left past the range";
    texture.values[1] = 1e5f;
    EXPECT_ANY_THROW(applyHalfRangePolicy(texture, true)) << "--strict refuses";
}

} // namespace
} // namespace iblkit::bake
