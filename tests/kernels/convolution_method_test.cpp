// planConvolution: the tree each roughness and budget give, and what it refuses.
#include "kernels/convolution_method.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace iblkit::kernels {
namespace {

TEST(ConvolutionPlan, LevelsNestFromFineToTop) {
    for (float roughness : {0.05f, 0.2f, 0.5f, 1.f}) {
        const auto plan = planConvolution(256, roughness, 128);
        EXPECT_LE(plan.fineLevel, plan.horizonLevel) << roughness;
        EXPECT_LE(plan.horizonLevel, plan.topLevel) << roughness;
        EXPECT_LE(plan.topLevel, 8u) << roughness; // 256² has levels 0 (256) to 8 (1)
        EXPECT_GE(plan.refine, 1.f) << roughness;
    }
    EXPECT_EQ(planConvolution(256, 0.2f, 128).fineLevel, 0u) << "a narrow lobe needs the source's own texels";
    EXPECT_GT(planConvolution(256, 1.f, 128).fineLevel, 2u) << "the widest lobe is resolved by 16 texels per face";
    EXPECT_GT(planConvolution(256, 0.5f, 1024).refine, planConvolution(256, 0.5f, 128).refine);
}

TEST(ConvolutionPlan, TheTopLevelHasAtMostTwoBlocksAcrossAFace) {
    // Below it every texel sums 6 top² terms whatever its budget: 384 at 1024², three times the
    // default budget, which made mip 1 of a 1024² bake 1.6 times slower and less accurate.
    for (const uint32_t size : {256u, 512u, 1024u, 4096u}) {
        const auto plan = planConvolution(size, 0.05f, 128);
        EXPECT_EQ(plan.fineLevel, 0u) << size;
        const uint32_t topBlocks = 6 * (size >> plan.topLevel) * (size >> plan.topLevel);
        EXPECT_LE(topBlocks, 24u) << size << ": the budget is left to the blocks near N";
        EXPECT_GE(plan.refine, 1.f) << size;
    }
    EXPECT_EQ(planConvolution(256, 0.05f, 128).topLevel, 7u) << "at 256² and below, 7 levels above the fine one, as before";
}

TEST(ConvolutionPlan, RefusesWhatItCannotSum) {
    EXPECT_THROW(planConvolution(256, 0.f, 128), std::invalid_argument);
    EXPECT_THROW(planConvolution(256, 1.5f, 128), std::invalid_argument);
    EXPECT_THROW(planConvolution(256, 0.5f, 0), std::invalid_argument);
    EXPECT_NO_THROW(planConvolution(256, 0.5f, kMaxConvolutionBudget));
    EXPECT_THROW(planConvolution(256, 0.5f, kMaxConvolutionBudget + 1), std::invalid_argument)
        << "past it, llvmpipe could end the walk's loop early";
    EXPECT_THROW(planConvolution(96, 0.5f, 128), std::invalid_argument) << "the walk steps through its top level by shifts";
}

} // namespace
} // namespace iblkit::kernels
