// The convolution's two pyramid layouts: one as wide as the source, holding its texels as level
// 0, and one half as wide, whose walk makes single texels where it reaches them. Both sum the same
// blocks in the same order, so every texel of every mip must be the same bit for bit.
#include "kernels/convolution_method.hpp"

#include "vulkan_test_support.hpp"

#include <bit>
#include <cmath>

namespace iblkit::kernels {
namespace {

constexpr uint32_t kSourceSize = 32;

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

    std::vector<float> walked(vulkan::Image& from, bool holdsSourceTexels, float roughness) {
        const uint32_t size = holdsSourceTexels ? kSourceSize : pyramidSize(kSourceSize);
        const uint32_t mips = uint32_t(std::bit_width(size));
        auto energy = cube("Energy", size, mips), centroid = cube("Centroid", size, mips), geometry = cube("Geometry", size, mips);
        vulkan::Image solidAngle(context(), {"TexelSolidAngle", &vulkan::texelFormatNamed("R32_SFLOAT"), kSourceSize, kSourceSize, 1, 1, false, true});
        const EnergyPyramid pyramid{energy, centroid, geometry, solidAngle, holdsSourceTexels};
        Kernel cluster(context(), compileKernel(kernelFor(KernelRole::ClusterCube)));
        runClusterPyramid(cluster, from, pyramid);
        Kernel walk(context(), compileConvolutionWalk("convolution", holdsSourceTexels));
        auto target = cube("Prefiltered", kSourceSize / 2, 1);
        const auto plan = planConvolution(kSourceSize, roughness, 128);
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

TEST_F(ConvolutionLayouts, SourcesUpTo512HoldTheirTexels) {
    EXPECT_TRUE(pyramidHoldsSourceTexels(256));
    EXPECT_TRUE(pyramidHoldsSourceTexels(512));
    EXPECT_FALSE(pyramidHoldsSourceTexels(1024)) << "three more RGBA32F cubes of 1024² would be 288 MiB";
}

} // namespace
} // namespace iblkit::kernels
