// The mip-chain method copies the source's own mips where the lobe is narrow and runs the
// pyramid's ring where it is wide: both halves bit for bit, and the count it does not take is
// refused.
#include "kernels/specular_method.hpp"

#include "pyramid_ring.hpp"
#include "vulkan_test_support.hpp"

#include <cmath>

namespace iblkit::kernels {
namespace {

constexpr uint32_t kSize = 32, kMips = 6;

class MipChainMethod : public iblkit::testing::VulkanTest {
protected:
    const vulkan::TexelFormat& rgba32_ = vulkan::texelFormatNamed("R32G32B32A32_SFLOAT");

    static float roughnessOf(uint32_t mip) { return float(mip) / float(kMips - 1); }

    // Every mip of every face different, so that a copy of the wrong mip or face shows.
    vulkan::Image source() {
        vulkan::Image image(context(), {"Source", &rgba32_, kSize, kSize, 6, kMips, true, false});
        std::vector<float> values(image.valueCount());
        for (size_t i = 0; i < values.size(); ++i) values[i] = 1.f + 0.5f * std::sin(0.37f * float(i));
        image.upload(context(), values);
        return image;
    }

    std::vector<float> prefiltered(const std::string& method, vulkan::Image& from) {
        vulkan::Image target(context(), {"Target", &rgba32_, kSize, kSize, 6, kMips, true, true});
        const vulkan::Sampler linear(context(), {});
        SpecularMethod prefilter(context(), method, 1);
        for (uint32_t mip = 1; mip < kMips; ++mip) prefilter.run(from, linear, target, mip, roughnessOf(mip));
        EXPECT_EQ(prefilter.takeTotals().dispatches, kMips - 1) << "one dispatch or copy per mip, each timed";
        return target.download(context());
    }

    std::vector<float> mipOf(const std::vector<float>& values, const vulkan::Image& image, uint32_t mip) {
        return {values.begin() + long(image.valueOffset(mip, 0)), values.begin() + long(image.valueOffset(mip + 1, 0))};
    }
};

TEST_F(MipChainMethod, NarrowMipsAreTheSourcesMipsAndWideOnesThePyramidsRing) {
    auto cube = source();
    const auto chain = prefiltered("mipchain", cube), pyramid = prefiltered("pyramid", cube);
    const auto sourceValues = cube.download(context());
    uint32_t copied = 0, ringed = 0;
    for (uint32_t mip = 1; mip < kMips; ++mip) {
        if (reference::pyramidRing(roughnessOf(mip), kSize)) {
            ++ringed;
            EXPECT_EQ(mipOf(chain, cube, mip), mipOf(pyramid, cube, mip)) << "mip " << mip << ": the ring's kernel";
        } else {
            ++copied;
            EXPECT_EQ(mipOf(chain, cube, mip), mipOf(sourceValues, cube, mip)) << "mip " << mip << ": a copy";
        }
    }
    EXPECT_GT(copied, 0u);
    EXPECT_GT(ringed, 0u);
}

TEST_F(MipChainMethod, TakesNoCount) {
    EXPECT_EQ(specularKindOf("mipchain"), SpecularKind::MipChain);
    EXPECT_EQ(maxSamplesOf("mipchain"), 1u);
    EXPECT_THROW(SpecularMethod(context(), "mipchain", 2), std::invalid_argument);
}

} // namespace
} // namespace iblkit::kernels
