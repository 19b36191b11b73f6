// The lobe table against what the lobe must be where it is known: head on, the split sum's lobe
// is the prefilter's own kernel; at roughness 1, D is constant and the lobe is G1(N·L) about N,
// whatever V is; near roughness 0 it is the mirror.
#include "shading/lobe_table.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace iblkit::shading {
namespace {

TEST(LobeTable, KernelRoughnessInvertsTheKernelsSpread) {
    const KernelRoughness inverse(LobeWeighting::G1);
    for (const double roughness : {0.02, 0.1, 0.3, 0.55, 0.9})
        EXPECT_NEAR(inverse.roughnessFor(kernelTangentVariance(roughness, LobeWeighting::G1)), roughness, 2e-3) << roughness;
    double previous = 0;
    for (int i = 1; i <= 20; ++i) {
        const double spread = kernelTangentVariance(i / 20.0, LobeWeighting::NdotL);
        EXPECT_GT(spread, previous) << "a rougher kernel spreads wider";
        previous = spread;
    }
}

TEST(LobeTable, HeadOnTheLobeIsThePrefiltersKernel) {
    for (const double roughness : {0.05, 0.3, 0.7}) {
        const auto fit = fitLobe(1.0, roughness, LobeWeighting::G1);
        // N = V = R: the lobe is D G1(N·L), the G1-weighted kernel itself, symmetric about R.
        EXPECT_NEAR(fit.roughness, roughness, 4e-3) << roughness;
        EXPECT_NEAR(fit.pairRoughness, roughness, 4e-3) << roughness;
        EXPECT_NEAR(fit.pairSpread, 0.0, 5e-3) << roughness;
    }
}

TEST(LobeTable, AtRoughnessOneTheLobeIsG1AboutTheNormal) {
    for (const double ndotv : {0.1, 0.5, 0.9}) {
        const auto fit = fitLobe(ndotv, 1.0, LobeWeighting::G1);
        EXPECT_NEAR(fit.blend, 0.0, 0.01) << ndotv << ": the mean direction is N";
        EXPECT_NEAR(fit.roughness, 1.0, 0.01) << ndotv;
        // G1 about N is round: the variances along and across the plane of N and V agree within
        // 2.4e-4 of 0.28 (the nodes' quadrature, at N·V = 0.1); the pair's spread is the arcsine of
        // the square root of their difference.
        EXPECT_LT(std::pow(std::sin(fit.pairSpread), 2), 1e-3) << ndotv;
    }
}

TEST(LobeTable, GrazingRoughLobesLeanTowardsTheNormalAndLengthen) {
    const auto grazing = fitLobe(0.2, 0.5, LobeWeighting::G1), headOn = fitLobe(0.95, 0.5, LobeWeighting::G1);
    EXPECT_LT(grazing.blend, 0.8);
    EXPECT_GT(headOn.blend, 0.85);
    EXPECT_GT(grazing.pairSpread, 2 * headOn.pairSpread);
    const auto mirror = fitLobe(0.2, 0.01, LobeWeighting::G1);
    EXPECT_NEAR(mirror.blend, 1.0, 0.01);
    EXPECT_LT(mirror.roughness, 0.02);
}

TEST(LobeTable, TheTableHoldsTheFitsAtItsTexelCentres) {
    const uint32_t size = 8;
    const auto table = lobeTable(size, LobeWeighting::G1);
    ASSERT_EQ(table.size(), size_t(size) * size * 4);
    const auto fit = fitLobe((3 + 0.5) / size, (5 + 0.5) / size, LobeWeighting::G1);
    const float* texel = &table[(5 * size + 3) * 4];
    EXPECT_EQ(texel[0], fit.blend);
    EXPECT_EQ(texel[1], fit.roughness);
    EXPECT_EQ(texel[2], fit.pairRoughness);
    EXPECT_EQ(texel[3], fit.pairSpread);
}

} // namespace
} // namespace iblkit::shading
