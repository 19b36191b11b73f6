// Each lod mapping against the engine's own formula, and the roughness of every mip as the
// mapping's inverse.
#include "shading/mip_schedule.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace iblkit::shading {
namespace {

TEST(MipSchedule, EachMappingIsItsEnginesFormula) {
    const MipSchedule linear{LodMapping::Linear, 1, 6, 256};
    EXPECT_DOUBLE_EQ(linear.lodOf(0.3), 0.3 * 5); // the documents: roughness * (mips - 1)
    const MipSchedule quadratic{LodMapping::Quadratic, 1, 6, 256};
    EXPECT_DOUBLE_EQ(quadratic.lodOf(0.3), 0.3 * (2 - 0.3) * 5); // three.js and Filament
    const MipSchedule power{LodMapping::Power, 0.5, 6, 256};
    EXPECT_DOUBLE_EQ(power.lodOf(0.25), 0.5 * 5);
    const MipSchedule babylon{LodMapping::Babylon, 1, 9, 256};
    EXPECT_DOUBLE_EQ(babylon.lodOf(0.5), 0.8 * std::log2(0.25 * 256)); // lodGenerationScale 0.8, α = r²
    EXPECT_DOUBLE_EQ(babylon.lodOf(0.01), 0.0);                         // below mip 0: the source
    EXPECT_DOUBLE_EQ(babylon.lodOf(1.0), 6.4);                          // short of the 1² mip
    EXPECT_DOUBLE_EQ((MipSchedule{LodMapping::Babylon, 1, 6, 256}.lodOf(1.0)), 5.0); // clamped to the chain
    const MipSchedule logarithmic{LodMapping::Logarithmic, 2, 6, 256};
    EXPECT_NEAR(logarithmic.lodOf(std::sqrt(2.0 / 256)), 1.0, 1e-12); // mip 1 at α size = c
    EXPECT_NEAR(logarithmic.lodOf(1.0), 5.0, 1e-12);                  // the last at roughness 1
    EXPECT_NEAR(logarithmic.lodOf(std::pow(2.0 / 256, 0.25)), 3.0, 1e-12) << "log α spaced evenly";
    const MipSchedule short2{LodMapping::Logarithmic, 2, 2, 16};
    EXPECT_DOUBLE_EQ(short2.lodOf(0.3), 0.3) << "two mips have no line between mip 1 and the last";
    EXPECT_DOUBLE_EQ(short2.roughnessOf(1), 1.0);
    EXPECT_DOUBLE_EQ((MipSchedule{LodMapping::Logarithmic, 4, 4, 4}.roughnessOf(2)), 2.0 / 3) << "faces no larger than c";
}

TEST(MipSchedule, EveryMipIsPrefilteredAtTheRoughnessItsLodReads) {
    for (const auto mapping : {LodMapping::Linear, LodMapping::Quadratic, LodMapping::Power, LodMapping::Babylon, LodMapping::Logarithmic}) {
        const MipSchedule schedule{mapping, 0.75, 9, 256};
        EXPECT_EQ(schedule.roughnessOf(0), 0.0) << nameOf(mapping);
        double previous = 0;
        for (uint32_t mip = 1; mip < schedule.mips; ++mip) {
            const double roughness = schedule.roughnessOf(mip);
            if (previous < 1) {
                EXPECT_GT(roughness, previous) << nameOf(mapping) << " mip " << mip;
            }
            previous = roughness;
            if (roughness < 1) {
                EXPECT_NEAR(schedule.lodOf(roughness), mip, 1e-9) << nameOf(mapping) << " mip " << mip;
            }
        }
    }
    EXPECT_DOUBLE_EQ((MipSchedule{LodMapping::Linear, 1, 6, 256}.roughnessOf(5)), 1.0);
}

TEST(MipSchedule, NamesRoundTripAndAnUnknownOneIsRefused) {
    for (const auto mapping : {LodMapping::Linear, LodMapping::Quadratic, LodMapping::Power, LodMapping::Babylon, LodMapping::Logarithmic})
        EXPECT_EQ(lodMappingNamed(nameOf(mapping)), mapping);
    EXPECT_THROW(lodMappingNamed("cubic"), std::invalid_argument);
}

} // namespace
} // namespace iblkit::shading
