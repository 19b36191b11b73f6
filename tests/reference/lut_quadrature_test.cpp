// The quadrature LUT's C++ twin (BrdfLutQuadratureCS): against the converged LUT, at the
// documents' hazards, and in float against double.
#include "converged_lut.hpp"
#include "lut_quadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace iblkit::reference {
namespace {

double largestDifference(const std::vector<double>& a, const std::vector<double>& b) {
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

TEST(LutQuadrature, SevenNodesAreWithinAFewMillionthsOfTheConvergedLut) {
    // 128²: measured 2.3e-6 in double at 7 nodes (the method's own error; 2.6e-6 at 512²) and
    // 2.9e-4 at 3 nodes, where the grazing column's panels are too coarse. Bounds 5e-6 and,
    // for the coarse rule, that it is worse: the twin's error must fall with the nodes.
    const auto converged = convergedBrdfLut(128);
    const double seven = largestDifference(brdfLutQuadrature<double>(128, 7), converged);
    EXPECT_LE(seven, 5e-6);
    EXPECT_GT(largestDifference(brdfLutQuadrature<double>(128, 3), converged), 10 * seven);
}

TEST(LutQuadrature, FloatFollowsDouble) {
    // The shader's arithmetic: measured 3.7e-6 from double at 128² (consistency suite).
    const auto inFloat = brdfLutQuadrature<float>(128, 7);
    const auto inDouble = brdfLutQuadrature<double>(128, 7);
    EXPECT_LE(largestDifference(std::vector<double>(inFloat.begin(), inFloat.end()), inDouble), 8e-6);
}

TEST(LutQuadrature, HazardsGiveTheLimitsAndNoNan) {
    const float denormal = std::numeric_limits<float>::denorm_min();
    for (const float ndotv : {0.f, denormal, 1e-7f, 1e-4f, 0.5f, 1.f - 1e-7f, 1.f})
        for (const float roughness : {0.f, denormal, 1e-4f, 0.01f, 0.5f, 1.f}) {
            const auto value = IntegrateBrdfQuadrature<float>(ndotv, 1.f - ndotv, roughness, 7);
            EXPECT_TRUE(std::isfinite(value.x) && std::isfinite(value.y)) << ndotv << " " << roughness;
            EXPECT_GE(value.x, 0.f);
            EXPECT_GE(value.y, 0.f);
            EXPECT_LE(value.x + value.y, 1.f + 1e-5f) << ndotv << " " << roughness; // G V.H / (N.H N.V) <= 1 on average
        }
    // Roughness 0 is the mirror: Schlick's terms at N.V.
    const auto mirror = IntegrateBrdfQuadrature<double>(0.3, 0.7, 0.0, 7);
    EXPECT_DOUBLE_EQ(mirror.y, std::pow(0.7, 5));
    EXPECT_DOUBLE_EQ(mirror.x, 1 - std::pow(0.7, 5));
    // Roughness 1e-4 is the mirror to 1e-6: the lobe has collapsed onto H = N.
    const auto nearMirror = IntegrateBrdfQuadrature<double>(0.3, 0.7, 1e-4, 7);
    EXPECT_NEAR(nearMirror.y, std::pow(0.7, 5), 1e-6);
    // N.V = 0 is finite for roughness > 0 and matches the converged integral there.
    const auto grazing = IntegrateBrdfQuadrature<double>(0.0, 1.0, 0.5, 7);
    const auto truth = convergedBrdf(0.0, 0.5);
    EXPECT_NEAR(grazing.x, truth.x, 5e-6);
    EXPECT_NEAR(grazing.y, truth.y, 5e-6);
}

} // namespace
} // namespace iblkit::reference
