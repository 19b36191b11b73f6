// The convolution's two pyramid layouts: one as wide as the source, holding its texels as level
// 0, and one half as wide, whose walk makes single texels where it reaches them. Both sum the same
// blocks in the same order, so every texel of every mip must be the same bit for bit.
#include "kernels/convolution_method.hpp"
#include "reference/cluster_convolution.hpp"

#include "vulkan_test_support.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace iblkit::kernels {
namespace {

constexpr uint32_t kSourceSize = 32;
// Relative error of the walk against the float reference on a 256² source: measured 3.1e-4, with
// or without the bright texel. The pyramids differ in their last bits (llvmpipe's atan2 in every
// texel's solid angle), and a block whose opening is that close to its threshold is summed whole by
// one and by its children in the other. Bound: twice that, rounded up.
constexpr double kWalkAgainstReference = 7e-4;

class ConvolutionLayouts : public iblkit::testing::VulkanTest {
protected:
    const vulkan::TexelFormat& rgba32_ = vulkan::texelFormatNamed("R32G32B32A32_SFLOAT");

    vulkan::Image cube(const std::string& name, uint32_t size, uint32_t mips) {
        return vulkan::Image(context(), {name, &rgba32_, size, size, 6, mips, true, true});
    }

    // Smooth light with one texel a thousand times brighter, so the walk opens blocks from afar.
    vulkan::Image source() {
        auto image = cube("Source", kSourceSize, 1);
        std::vector<float> values(image.valueCount());
        for (size_t i = 0; i < values.size(); ++i) values[i] = 1.f + 0.5f * std::sin(0.37f * float(i));
        for (size_t c = 0; c < 3; ++c) values[4 * (2 * kSourceSize * kSourceSize + 9 * kSourceSize + 20) + c] = 1000.f;
        image.upload(context(), values);
        return image;
    }

    // Mip 0 of an outSize cube walked from `from`'s pyramid of either layout.
    std::vector<float> walked(vulkan::Image& from, bool holdsSourceTexels, float roughness, uint32_t outSize = kSourceSize / 2) {
        const uint32_t sourceSize = from.desc().width;
        const uint32_t size = holdsSourceTexels ? sourceSize : pyramidSize(sourceSize);
        const uint32_t mips = uint32_t(std::bit_width(size));
        auto energy = cube("Energy", size, mips), centroid = cube("Centroid", size, mips), geometry = cube("Geometry", size, mips);
        vulkan::Image solidAngle(context(), {"TexelSolidAngle", &vulkan::texelFormatNamed("R32_SFLOAT"), sourceSize, sourceSize, 1, 1, false, true});
        const EnergyPyramid pyramid{energy, centroid, geometry, solidAngle, holdsSourceTexels};
        Kernel cluster(context(), compileKernel(kernelFor(KernelRole::ClusterCube)));
        runClusterPyramid(cluster, from, pyramid);
        Kernel walk(context(), compileConvolutionWalk("convolution", holdsSourceTexels));
        auto target = cube("Prefiltered", outSize, 1);
        const auto plan = planConvolution(sourceSize, roughness, 128);
        runPrefilterConvolution(walk, from, pyramid, target, 0,
                                {roughness, plan.topLevel, plan.fineLevel, plan.refine, plan.horizonLevel, 1});
        return target.download(context());
    }
};

TEST_F(ConvolutionLayouts, SumTheSameBlocksBitForBit) {
    auto from = source();
    for (const float roughness : {0.05f, 0.3f, 1.f}) {
        const auto inPyramid = walked(from, true, roughness), madeByTheWalk = walked(from, false, roughness);
        ASSERT_EQ(inPyramid.size(), madeByTheWalk.size());
        size_t differing = 0;
        for (size_t i = 0; i < inPyramid.size(); ++i) differing += inPyramid[i] != madeByTheWalk[i];
        EXPECT_EQ(differing, 0u) << "roughness " << roughness;
        EXPECT_GT(inPyramid[0], 0.f) << "roughness " << roughness << ": something was summed";
    }
    EXPECT_EQ(planConvolution(kSourceSize, 0.05f, 128).fineLevel, 0u) << "the narrowest lobe reaches single texels";
}

// ConvolutionPrefilter picks the layout by the source's width: a 32² source past a limit of 16 is
// walked through the half-width pyramid, by the walk compiled when it is first needed.
TEST_F(ConvolutionLayouts, ThePrefilterWalksEitherLayoutToTheSameMips) {
    auto from = source();
    const vulkan::Sampler linear(context(), {});
    const auto prefiltered = [&](uint32_t maxSourceTexelsInPyramid) {
        auto target = cube("Target", kSourceSize, 4);
        ConvolutionPrefilter prefilter(context(), "convolution", 128, embeddedShaderFiles(), 0, maxSourceTexelsInPyramid);
        prefilter.setWeighting(shading::LobeWeighting::G1);
        for (uint32_t mip = 1; mip < 4; ++mip) prefilter.run(from, target, mip, 0.1f * float(mip * mip));
        const uint32_t pyramidWidth = kSourceSize <= maxSourceTexelsInPyramid ? kSourceSize : kSourceSize / 2;
        EXPECT_EQ(prefilter.takeTotals().dispatches, uint32_t(std::bit_width(pyramidWidth)) + 3u)
            << "the pyramid's levels once (as wide as the source, or half), then one walk per mip";
        const auto values = target.download(context()); // mip 0 is never written
        return std::vector<float>(values.begin() + long(target.valueOffset(1, 0)), values.end());
    };
    const auto inPyramid = prefiltered(kMaxSourceTexelsInPyramid), madeByTheWalk = prefiltered(16);
    EXPECT_EQ(inPyramid, madeByTheWalk);
}

// At 256² and a narrow lobe the walk starts from 2 x 2 blocks per face, so it steps through its
// top level by shifts and masks across faces: against the C++ reference, which divides.
TEST_F(ConvolutionLayouts, AWalkFromTwoBlocksPerFaceIsTheReferences) {
    constexpr uint32_t size = 256, outSize = 8;
    const float roughness = 0.1f;
    const auto plan = planConvolution(size, roughness, 128);
    ASSERT_EQ(size >> plan.topLevel, 2u);
    std::vector<float> texels(size_t(size) * size * 6 * 4);
    for (size_t i = 0; i < texels.size(); ++i) texels[i] = 1.f + 0.5f * std::sin(0.0137f * float(i));
    for (size_t c = 0; c < 3; ++c) texels[4 * (3 * size * size + 40 * size + 200) + c] = 5000.f;
    auto from = cube("Source", size, 1);
    from.upload(context(), texels);
    const auto onDevice = walked(from, true, roughness, outSize);
    const reference::ConvolutionTree tree{plan.topLevel, plan.fineLevel, plan.refine, plan.horizonLevel, 1};
    const auto expected = reference::convolvePrefilter(reference::clusterPyramid<float>(texels, size), roughness, outSize, tree);
    ASSERT_EQ(onDevice.size(), expected.size());
    double largest = 0;
    for (size_t i = 0; i < onDevice.size(); ++i)
        largest = std::max(largest, std::abs(double(onDevice[i]) - expected[i]) / std::max(1.0, double(std::abs(expected[i]))));
    EXPECT_LT(largest, kWalkAgainstReference) << "a block visited twice, or one left out, moves a texel by percents";
}

TEST(ConvolutionPyramidSize, IsTheSourcesUpTo512AndHalfOfItAbove) {
    EXPECT_EQ(convolutionPyramidSize(256), 256u) << "the default bake's source keeps its texels";
    EXPECT_EQ(convolutionPyramidSize(512), 512u);
    EXPECT_EQ(convolutionPyramidSize(1024), 512u) << "three more RGBA32F cubes of 1024² would be 288 MiB";
    EXPECT_EQ(convolutionPyramidSize(1), 1u) << "a single texel is a whole face, made by the walk";
    EXPECT_FALSE(pyramidHoldsSourceTexels(1));
}

} // namespace
} // namespace iblkit::kernels
