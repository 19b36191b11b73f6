// The convolution method's reference: exact on a constant environment, and converging on the
// converged prefilter as the tree opens more blocks.
#include "cluster_convolution.hpp"
#include "converged_prefilter.hpp"
#include "cube_environment.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace iblkit::reference {
namespace {

double largestRelativeError(const std::vector<double>& texels, uint32_t outSize, const std::vector<glm::dvec3>& truth,
                            const std::vector<PrefilterTexel>& at) {
    double largest = 0;
    for (size_t i = 0; i < at.size(); ++i) {
        const size_t index = ((size_t(at[i].face) * outSize + at[i].y) * outSize + at[i].x) * 4;
        for (int c = 0; c < 3; ++c)
            largest = std::max(largest, std::abs(texels[index + c] - truth[i][c]) / std::max(truth[i][c], 1e-6));
    }
    return largest;
}

TEST(ClusterConvolution, AConstantEnvironmentIsReturnedExactly) {
    const uint32_t size = 16;
    std::vector<float> constant;
    for (size_t i = 0; i < size_t(6) * size * size; ++i) constant.insert(constant.end(), {0.5f, 2.f, 8.f, 1.f});
    const auto pyramid = clusterPyramid<double>(constant, size);
    for (double roughness : {0.1, 0.5, 1.0}) {
        const auto texels = convolvePrefilter(pyramid, roughness, 8, {4, 0, 1.5, 2});
        double worst = 0;
        for (size_t i = 0; i < texels.size(); i += 4)
            worst = std::max({worst, std::abs(texels[i] / 0.5 - 1), std::abs(texels[i + 1] / 2.0 - 1), std::abs(texels[i + 2] / 8.0 - 1)});
        // The same blocks weigh numerator and denominator, so only rounding separates the result
        // from the constant: the light's mean direction and the blocks' extent are each a sum
        // times a reciprocal, whose last bits a narrow lobe's steep slope amplifies (measured
        // 2.3e-13 relative at roughness 0.1, 1.3e-15 at 0.5): the bound at twice the worst.
        EXPECT_LT(worst, 5e-13) << roughness;
    }
}

TEST(ClusterConvolution, ConvergesOnTheConvergedPrefilterAsTheTreeOpens) {
    const uint32_t size = 32, outSize = 8;
    const auto source = CubeEnvironment::testEnvironment(size).texels();
    const auto pyramid = clusterPyramid<double>(source, size);
    const auto at = seededPrefilterTexels(outSize, 64, 1);
    const auto truth = convergedPrefilter(source, size, 0.5, outSize, at);
    const auto coarse = largestRelativeError(convolvePrefilter(pyramid, 0.5, outSize, {5, 0, 1.0, 2}), outSize, truth, at);
    const auto fine = largestRelativeError(convolvePrefilter(pyramid, 0.5, outSize, {5, 0, 4.0, 0}), outSize, truth, at);
    // Measured 3.1e-2 with blocks opened within 1 of their widths and a coarse horizon, 2.4e-3
    // within 4 and the horizon opened to the texels: bounds at twice those.
    EXPECT_LT(coarse, 6e-2);
    EXPECT_LT(fine, 5e-3);
    EXPECT_LT(fine, coarse / 4) << "opening more blocks must converge";
}

// A light far brighter than the rest outweighs the lobe's fall-off: its blocks must open from
// farther away than the others, or a block holding part of an extended light (a strip, like a
// studio's softbox) is taken whole close to the lobe, its spread far from isotropic.
TEST(ClusterConvolution, ABrightStripIsResolvedFromFarther) {
    const uint32_t size = 64, outSize = 16;
    std::vector<float> source;
    for (size_t i = 0; i < size_t(6) * size * size; ++i) source.insert(source.end(), {1.f, 1.f, 1.f, 1.f});
    for (uint32_t y = 16; y < 48; ++y)
        for (uint32_t x = 40; x < 42; ++x)
            for (int c = 0; c < 3; ++c) source[((size_t(4) * size + y) * size + x) * 4 + c] = 100.f;
    const auto pyramid = clusterPyramid<double>(source, size);
    const auto at = seededPrefilterTexels(outSize, 256, 3);
    const auto truth = convergedPrefilter(source, size, 0.2, outSize, at);
    const auto error = largestRelativeError(convolvePrefilter(pyramid, 0.2, outSize, {6, 0, 1.0, 0}), outSize, truth, at);
    // Measured 9.6e-3; 9.0e-2 when every block opens within the same reach, bright or not.
    EXPECT_LT(error, 2e-2);
}

} // namespace
} // namespace iblkit::reference
