// The quadrature-grid LUT's C++ twin (BrdfLutGridCS, then BrdfLutResampleCS): its interpolation
// on a known function, against the converged LUT, and in float against double.
#include "converged_lut.hpp"
#include "lut_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace iblkit::reference {
namespace {

template <typename T>
double largestDifference(const std::vector<T>& a, const std::vector<double>& b) {
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(double(a[i]) - b[i]));
    return worst;
}

TEST(LutGrid, InterpolationIsExactForQuadraticsInTheGridsCoordinates) {
    // Catmull-Rom with quadratic end neighbours reproduces any quadratic in (u, w) = (cbrt N.V,
    // cbrt roughness), end intervals included: a wrong weight, node or extrapolation breaks it.
    const uint32_t gridSize = 6, size = 40;
    const auto quadratic = [](double u, double w) { return glm::dvec2(1 + 2 * u - 3 * u * w + w * w, u * u - w); };
    std::vector<double> grid;
    for (uint32_t j = 0; j < gridSize; ++j)
        for (uint32_t i = 0; i < gridSize; ++i) {
            const auto value = quadratic(double(i) / (gridSize - 1), double(j) / (gridSize - 1));
            grid.insert(grid.end(), {value.x, value.y});
        }
    const auto lut = resampleBrdfLutGrid<double>(grid, gridSize, size);
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const auto expected = quadratic(std::cbrt((x + 0.5) / size), std::cbrt((y + 0.5) / size));
            ASSERT_NEAR(lut[(y * size + x) * 2], expected.x, 1e-12) << x << " " << y;
            ASSERT_NEAR(lut[(y * size + x) * 2 + 1], expected.y, 1e-12) << x << " " << y;
        }
}

TEST(LutGrid, ErrorFallsWithTheGridToTheRg32fTarget) {
    // 128² against the converged LUT, in double: measured 1.6e-3 at a 32² grid and 8.6e-6 at
    // 128², the largest error at the grazing column of low roughness, where the LUT turns over
    // N.V ~ roughness² / 2 (bounds twice those). A finer grid must be far better.
    const auto converged = convergedBrdfLut(128);
    const auto coarse = largestDifference(resampleBrdfLutGrid<double>(brdfLutGridNodes<double>(32, 7), 32, 128), converged);
    const auto fine = largestDifference(resampleBrdfLutGrid<double>(brdfLutGridNodes<double>(128, 7), 128, 128), converged);
    EXPECT_LE(coarse, 3.2e-3);
    EXPECT_LE(fine, 1.8e-5);
    EXPECT_GT(coarse, 10 * fine);
}

TEST(LutGrid, FloatFollowsDouble) {
    // The shaders' arithmetic: measured 2.3e-6 from double at a 64² grid and a 128² LUT (bound twice).
    const auto nodesFloat = brdfLutGridNodes<float>(64, 7);
    const auto nodesDouble = brdfLutGridNodes<double>(64, 7);
    EXPECT_LE(largestDifference(resampleBrdfLutGrid<float>(nodesFloat, 64, 128),
                                resampleBrdfLutGrid<double>(nodesDouble, 64, 128)),
              5e-6);
}

TEST(LutGrid, RefusesGridsTooSmallToInterpolate) {
    const auto grid = brdfLutGridNodes<double>(3, 7);
    EXPECT_THROW(resampleBrdfLutGrid<double>(grid, 3, 16), std::invalid_argument);
    EXPECT_THROW(resampleBrdfLutGrid<double>(grid, 4, 16), std::invalid_argument); // size mismatch
}

} // namespace
} // namespace iblkit::reference
