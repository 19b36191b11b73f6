// Sample counts past llvmpipe's loop limit (65535 iterations, after which a loop silently
// ends) run as chunks of dispatches, and compute what a single loop would have: the chunked
// kernels agree with the documents' shaders, and 2^18 samples agree with 2^16.
#include "kernels/kernel_steps.hpp"
#include "kernels/sampled_methods.hpp"

#include "converged_lut.hpp"
#include "cube_environment.hpp"
#include "vulkan_test_support.hpp"

#include <cmath>

namespace iblkit::kernels {
namespace {

class SampledMethods : public iblkit::testing::VulkanTest {
protected:
    std::vector<float> lut(uint32_t samples, uint32_t chunk, uint32_t size = 16) {
        BrdfLutMethod method(context(), "document", samples, chunk);
        vulkan::Image image(context(), {"Lut", &vulkan::texelFormatNamed("R32G32_SFLOAT"), size, size, 1, 1, false, true});
        method.run(image);
        return image.download(context());
    }

    std::vector<float> prefilter(uint32_t samples, uint32_t chunk, float roughness) {
        const auto environment = reference::CubeEnvironment::testEnvironment(32);
        const auto& rgba32 = vulkan::texelFormatNamed("R32G32B32A32_SFLOAT");
        vulkan::Image source(context(), {"Source", &rgba32, 32, 32, 6, 1, true, false});
        source.upload(context(), environment.texels());
        vulkan::Image target(context(), {"Target", &rgba32, 16, 16, 6, 2, true, true});
        const vulkan::Sampler linear(context(), {});
        PrefilterMethod method(context(), "document", samples, chunk);
        method.run(source, linear, target, 1, roughness);
        const auto values = target.download(context());
        return {values.begin() + long(target.valueOffset(1, 0)), values.end()};
    }

    static double largestDifference(const std::vector<float>& a, const std::vector<float>& b, bool relative) {
        double worst = 0;
        for (size_t i = 0; i < a.size(); ++i) {
            const double difference = std::abs(double(a[i]) - b[i]);
            worst = std::max(worst, relative ? difference / std::max(1e-6, std::abs(double(b[i]))) : difference);
        }
        return worst;
    }
};

TEST(ChunkSchedule, OnlyCountsPastTheLoopLimitAreSplit) {
    EXPECT_EQ(chunkSamplesFor(1024), 0u);
    EXPECT_EQ(chunkSamplesFor(kLoopLimit), 0u);
    EXPECT_EQ(chunkSamplesFor(kLoopLimit + 1), kChunkSamples);
    EXPECT_EQ(chunkSamplesFor(1024, 100), 100u);
    EXPECT_THROW(chunkSamplesFor(1024, kLoopLimit + 1), std::invalid_argument);
}

TEST_F(SampledMethods, OneChunkIsTheDocumentsLut) {
    // The chunked kernel's per-sample math is the document's: as one chunk it computes the same
    // sums in the same order. Measured 0: bit for bit.
    EXPECT_EQ(largestDifference(lut(1024, 1024), lut(1024, 0), false), 0.0);
}

TEST_F(SampledMethods, OneChunkIsTheDocumentsPrefilter) {
    // Measured 0: bit for bit, as for the LUT.
    EXPECT_EQ(largestDifference(prefilter(1024, 1024, 0.4f), prefilter(1024, 0, 0.4f), false), 0.0);
}

TEST_F(SampledMethods, ChunksAddUpToTheDocumentsLut) {
    // Seven uneven chunks change only the order of the float additions of 1024 terms.
    // Measured 1.07e-6 on values up to 1.1; bound 2.2e-6.
    EXPECT_LE(largestDifference(lut(1024, 150), lut(1024, 0), false), 2.2e-6);
}

TEST_F(SampledMethods, ChunksAddUpToTheDocumentsPrefilter) {
    // Eleven chunks regroup the float sums of radiance and weight. Measured 2.4e-6 relative;
    // bound 5e-6.
    EXPECT_LE(largestDifference(prefilter(1024, 100, 0.4f), prefilter(1024, 0, 0.4f), true), 5e-6);
}

TEST_F(SampledMethods, LutAt2To18AgreesWith2To16) {
    // Past the loop limit, an unsplit loop stops at sample 65535 and the LUT's mean halves.
    // Split, both counts estimate the same integral, and the larger one more closely: measured
    // max error 5.4e-4 at 2^16 and 2.7e-4 at 2^18 against the converged quadrature (the
    // grazing column), their largest difference 5.9e-4. The unsplit loop is off by ~0.3.
    const auto converged = reference::convergedBrdfLut(16);
    const std::vector<float> truth(converged.begin(), converged.end());
    const auto many = lut(1u << 18, 0), fewer = lut(1u << 16, 0);
    const double errorMany = largestDifference(many, truth, false), errorFewer = largestDifference(fewer, truth, false);
    EXPECT_LE(errorMany, errorFewer);
    EXPECT_LE(errorFewer, 1.1e-3); // measured 5.4e-4
    EXPECT_LE(largestDifference(many, fewer, false), 1.2e-3); // measured 5.9e-4
}

TEST_F(SampledMethods, PrefilterAt2To18AgreesWith2To16) {
    // Measured 5.0e-5 relative on the smooth test sky at roughness 0.3 (the 2^16 estimate's
    // own error there); bound 1e-4. An unsplit 2^18 loop covers only a quarter of the
    // Hammersley azimuths and is off by tens of percent.
    const auto many = prefilter(1u << 18, 0, 0.3f), fewer = prefilter(1u << 16, 0, 0.3f);
    EXPECT_LE(largestDifference(many, fewer, true), 1e-4);
}

} // namespace
} // namespace iblkit::kernels
