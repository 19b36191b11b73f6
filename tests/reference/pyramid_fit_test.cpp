// The pyramid prefilter's host half: reads of the mip chain along the normal whose kernels,
// summed, fit the GGX lobe.
#include "filtered_prefilter.hpp"
#include "pyramid_fit.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace iblkit::reference {
namespace {

TEST(PyramidFit, WeightsArePositiveAndSumToOneWithinTheChain) {
    for (uint32_t reads = 1; reads <= kMaxPyramidReads; ++reads)
        for (double roughness : {0.05, 0.2, 0.4, 0.6, 0.8, 1.0}) {
            const auto fit = fitPyramidReads(roughness, reads, 256);
            ASSERT_FALSE(fit.empty());
            EXPECT_LE(fit.size(), reads);
            double total = 0;
            for (const auto& read : fit) {
                EXPECT_GT(read.weight, 0.f);
                EXPECT_GE(read.lod, 0.f);
                EXPECT_LE(read.lod, 8.f) << "a 256² cube has mips 0 to 8";
                total += read.weight;
            }
            EXPECT_NEAR(total, 1.0, 1e-6) << roughness << ", " << reads << " reads";
        }
}

// A wider lobe is read further up the chain.
TEST(PyramidFit, OneReadClimbsTheChainWithTheRoughness) {
    float previous = -1;
    for (double roughness : {0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6}) {
        const auto fit = fitPyramidReads(roughness, 1, 256);
        ASSERT_EQ(fit.size(), 1u);
        EXPECT_GT(fit[0].lod, previous) << roughness;
        previous = fit[0].lod;
    }
}

// The lobe is the same on a cube twice as wide, with four times the texels under it: every read
// moves exactly one mip up (the fit runs on the same coarsened grid for both).
TEST(PyramidFit, ACubeTwiceAsWideReadsOneMipHigher) {
    for (double roughness : {0.4, 0.6, 1.0}) {
        const auto small = fitPyramidReads(roughness, 2, 128), large = fitPyramidReads(roughness, 2, 256);
        ASSERT_EQ(small.size(), large.size()) << roughness;
        for (size_t i = 0; i < small.size(); ++i) {
            EXPECT_EQ(large[i].lod, small[i].lod + 1) << roughness;
            EXPECT_EQ(large[i].weight, small[i].weight) << roughness;
        }
    }
}

TEST(PyramidFit, RoughnessZeroIsAMirrorOfMipZero) {
    const auto fit = fitPyramidReads(0.0, 2, 64);
    ASSERT_EQ(fit.size(), 1u);
    EXPECT_EQ(fit[0].lod, 0.f);
    EXPECT_EQ(fit[0].weight, 1.f);
}

TEST(PyramidFit, RefusesCountsAndSizesItCannotFit) {
    EXPECT_THROW(fitPyramidReads(0.5, 0, 64), std::invalid_argument);
    EXPECT_THROW(fitPyramidReads(0.5, kMaxPyramidReads + 1, 64), std::invalid_argument);
    EXPECT_THROW(fitPyramidReads(0.5, 1, 48), std::invalid_argument);
}

// Weights that sum to 1 return a constant environment exactly, at every texel and roughness.
TEST(PyramidFit, AConstantEnvironmentStaysConstant) {
    MippedCube cube{16, 5, {}};
    for (uint32_t mip = 0; mip < cube.mips; ++mip)
        for (uint32_t texel = 0; texel < 6 * cube.mipSize(mip) * cube.mipSize(mip); ++texel)
            cube.texels.insert(cube.texels.end(), {0.5f, 2.f, 3.f, 1.f});
    const MippedEnvironment source(cube);
    for (double roughness : {0.25, 0.5, 1.0}) {
        const auto texels = referencePyramidPrefilter<double>(source, fitPyramidReads(roughness, 3, 16), 8);
        for (size_t i = 0; i < texels.size(); i += 4) {
            EXPECT_NEAR(texels[i], 0.5, 1e-6);
            EXPECT_NEAR(texels[i + 1], 2.0, 1e-6);
            EXPECT_NEAR(texels[i + 2], 3.0, 1e-6);
        }
    }
}

} // namespace
} // namespace iblkit::reference
