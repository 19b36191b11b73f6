// The documents' kernels are faithful, singular points included: their C++ twin (the same
// arithmetic in float) shows where. The bake never feeds them one: the LUT shader evaluates texel
// centres only, and the prefilter runs only for mips of positive roughness (mip 0 is a copy).
#include "bake_settings.hpp"

#include "pbr.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>

namespace iblkit::bake {
namespace {

using reference::IntegrateBRDF;

TEST(DocumentInputs, TheDocumentsLutIsSingularAtGrazingViewOnly) {
    // N·V = 0: G's Schlick term is 0 / k and the visibility divides it by N·H · N·V = 0.
    const auto grazing = IntegrateBRDF<float>(0.f, 0.5f, 64);
    EXPECT_FALSE(std::isfinite(grazing.x) && std::isfinite(grazing.y)) << "the document's 0/0 at N·V = 0";
    // Roughness 0 is not singular in the estimator: every half vector is N, and G = 1.
    const auto mirror = IntegrateBRDF<float>(0.5f, 0.f, 64);
    EXPECT_TRUE(std::isfinite(mirror.x) && std::isfinite(mirror.y));
    // D itself is 0/0 at roughness 0 and N·H = 1 (the second document's mirror limit); the
    // estimator never evaluates it, the prefilter weights by N·L alone.
    EXPECT_TRUE(std::isnan(reference::DistributionGGX<float>(1.f, 0.f)));
}

TEST(DocumentInputs, TheBakeFeedsTheLutTexelCentresOnly) {
    // PrecomputedBrdfCS reads N·V and roughness at (texel + 0.5) / size: at the largest size the
    // bake takes the smallest is 0.5 / 16384, where the estimator is finite.
    const float smallest = 0.5f / float(kMaxLutSize);
    EXPECT_GT(smallest, 0.f);
    for (const float roughness : {smallest, 0.5f, 1.f - smallest}) {
        const auto value = IntegrateBRDF<float>(smallest, roughness, 1024);
        EXPECT_TRUE(std::isfinite(value.x) && std::isfinite(value.y)) << "roughness " << roughness;
    }
}

TEST(DocumentInputs, TheBakePrefiltersOnlyAtPositiveRoughness) {
    // Every face size the bake takes, with every mip count up to its full chain (down to 1²):
    // the first prefiltered mip, mip 1, has roughness 1 / (mips - 1) > 0; mip 0 is the copied
    // source, and a single mip prefilters nothing.
    for (uint32_t size = 1; size <= kMaxCubeSize; size *= 2) {
        BakeSettings settings;
        settings.size = size;
        settings.mips = uint32_t(std::bit_width(size));
        EXPECT_EQ(resolveSettings(settings).mipCount, *settings.mips) << "the full chain is allowed at " << size << "²";
        for (uint32_t mips = 2; mips <= *settings.mips; ++mips)
            EXPECT_GT(roughnessOfMip(1, mips), 0.f) << size << "² with " << mips << " mips";
    }
}

} // namespace
} // namespace iblkit::bake
