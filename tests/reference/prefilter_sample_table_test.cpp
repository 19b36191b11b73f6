// The sample-table method's host half: the document's samples about +Z, each with the lod whose
// texels cover its share of the sphere.
#include "prefilter_sample_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace iblkit::reference {
namespace {

TEST(PrefilterSampleTable, EntriesAreUnitDirectionsAboveTheHorizon) {
    for (double roughness : {0.05, 0.3, 0.7, 1.0}) {
        const auto table = prefilterSampleTable(roughness, 1024, 256);
        ASSERT_FALSE(table.empty()) << roughness;
        EXPECT_LE(table.size(), 1024u);
        for (const auto& entry : table) {
            EXPECT_GT(entry.z, 0.f) << roughness;
            EXPECT_NEAR(std::hypot(entry.x, entry.y, entry.z), 1.0, 1e-6) << roughness;
        }
    }
    // L = 2 (N·H) H − N is above the horizon for N·H > 1/sqrt(2): a narrow lobe keeps every sample,
    // the widest (GGX at alpha 1 is uniform in N·H², so half of them) about half.
    EXPECT_EQ(prefilterSampleTable(0.05, 1024, 256).size(), 1024u);
    EXPECT_NEAR(double(prefilterSampleTable(1.0, 1024, 256).size()), 512.0, 2.0);
}

// The lods say what solid angle each sample stands for, 1 / (n pdf): 4^lod texels of mip 0's
// face centre. Summed over the samples kept, that is the Monte Carlo estimate of the hemisphere
// above the horizon, 2 pi. Measured within 0.7 % at roughness 0.3 to 1 (Hammersley points);
// bound 2 %. A lod off by a factor of 2 in its log gives 4^lod off by orders of magnitude.
TEST(PrefilterSampleTable, LodsCoverTheHemisphere) {
    const uint32_t size = 256;
    const double texelSolidAngle = 4.0 / (double(size) * size);
    for (double roughness : {0.3, 0.6, 1.0}) {
        double covered = 0;
        for (const auto& entry : prefilterSampleTable(roughness, 4096, size))
            covered += texelSolidAngle * std::pow(4.0, double(entry.w));
        EXPECT_NEAR(covered / (2 * std::numbers::pi), 1.0, 0.02) << roughness;
    }
}

TEST(PrefilterSampleTable, RoughnessZeroIsAMirror) {
    const auto table = prefilterSampleTable(0.0, 64, 256);
    ASSERT_EQ(table.size(), 64u);
    for (const auto& entry : table) {
        EXPECT_EQ(entry.z, 1.f);
        EXPECT_EQ(entry.w, float(kMirrorLod)) << "D is 0/0: the lobe is a delta, read at mip 0";
    }
    EXPECT_EQ(filteredSourceLod(1.0, 0.0, 64, 256), kMirrorLod);
}

TEST(PrefilterSampleTable, MoreSamplesReadFinerMips) {
    // Each quadrupling of the count halves a sample's footprint's side: one mip down.
    EXPECT_NEAR(filteredSourceLod(0.9, 0.5, 256, 256) - filteredSourceLod(0.9, 0.5, 1024, 256), 1.0, 1e-12);
    EXPECT_NEAR(filteredSourceLod(0.9, 0.5, 256, 512) - filteredSourceLod(0.9, 0.5, 256, 256), 1.0, 1e-12);
}

} // namespace
} // namespace iblkit::reference
