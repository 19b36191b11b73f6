// The pyramid method's ring for wide lobes: the lobe's mass quantiles, where the ring takes over,
// and its reads' lods.
#include "pyramid_ring.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace iblkit::reference {
namespace {

TEST(PyramidRing, QuantilesOfTheRoughestLobeAreExact) {
    // At roughness 1, D = 1/π everywhere: the mass within θ is sin²θ of the whole, so the angles
    // holding half and three quarters of it are π/4 and π/3. Measured within 1.9e-8 (bound 1e-7).
    EXPECT_NEAR(lobeQuantileAngle(1.0, 0.5), std::numbers::pi / 4, 1e-7);
    EXPECT_NEAR(lobeQuantileAngle(1.0, 0.75), std::numbers::pi / 3, 1e-7);
    EXPECT_EQ(lobeQuantileAngle(1.0, 0.0), 0.0);
    EXPECT_LT(lobeQuantileAngle(0.3, 0.5), lobeQuantileAngle(0.6, 0.5)) << "a rougher lobe is wider";
}

TEST(PyramidRing, TakesOverWhereHalfTheLobeLiesPastAnEighthOfPi) {
    // Half the mass lies within 0.28 rad at roughness 0.4 and 0.40 at 0.5 (π/8 = 0.39).
    EXPECT_FALSE(pyramidRing(0.2, 256));
    EXPECT_FALSE(pyramidRing(0.4, 256));
    for (const double roughness : {0.5, 0.6, 0.8, 1.0}) EXPECT_TRUE(pyramidRing(roughness, 256)) << roughness;
}

TEST(PyramidRing, ReadsSitWhereTheLobesMassSaysAtLodsOfTheirSpacing) {
    // Roughness 1 on 256² faces (a texel 2/256 wide at a face centre): the ring at π/3, the centre
    // a texel of π/4 half a level up, the ring a texel as wide as its 8 reads are apart.
    const auto ring = pyramidRing(1.0, 256);
    ASSERT_TRUE(ring);
    const double texel = 2.0 / 256;
    EXPECT_NEAR(ring->cosAngle, 0.5, 1e-6);
    EXPECT_NEAR(ring->centreLod, std::log2(std::numbers::pi / 4 / texel) + 0.5, 1e-5);
    EXPECT_NEAR(ring->ringLod, std::log2(2 * std::numbers::pi * std::sin(std::numbers::pi / 3) / kPyramidRingReads / texel), 1e-5);
    EXPECT_EQ(ring->centreWeight, 0.5f);
}

TEST(PyramidRing, LodsStayInsideTheChainAtEverySize) {
    // On a 1² cube the ring's spacing is a fraction of the one texel: lod 0, not below.
    for (uint32_t size = 1; size <= 4096; size *= 2)
        for (const double roughness : {0.5, 0.75, 1.0}) {
            const auto ring = pyramidRing(roughness, size);
            ASSERT_TRUE(ring);
            const float top = float(std::log2(size));
            EXPECT_GE(ring->centreLod, 0.f);
            EXPECT_LE(ring->centreLod, top) << size;
            EXPECT_GE(ring->ringLod, 0.f);
            EXPECT_LE(ring->ringLod, top) << size;
        }
}

} // namespace
} // namespace iblkit::reference
