// The quadrature-grid LUT's C++ twin (BrdfLutGridCS, then BrdfLutResampleCS): its interpolation
// on a known function, against the converged LUT, and in float against double.
#include "converged_lut.hpp"
#include "lut_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace iblkit::reference {
namespace {

template <typename T>
double largestDifference(const std::vector<T>& a, const std::vector<double>& b) {
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(double(a[i]) - b[i]));
    return worst;
}

// The grid's coordinates of a texel: u = cbrt(1 - sqrt(1 - N.V)), w = cbrt(roughness).
glm::dvec2 gridCoordinates(double ndotv, double roughness) {
    return {std::cbrt(1 - std::sqrt(1 - ndotv)), std::cbrt(roughness)};
}

std::vector<double> gridOf(uint32_t gridSize, const std::function<glm::dvec2(double, double)>& value) {
    std::vector<double> grid;
    for (uint32_t j = 0; j < gridSize; ++j)
        for (uint32_t i = 0; i < gridSize; ++i) {
            const auto node = value(double(i) / (gridSize - 1), double(j) / (gridSize - 1));
            grid.insert(grid.end(), {node.x, node.y});
        }
    return grid;
}

TEST(LutGrid, InterpolationIsExactForQuadraticsInTheGridsCoordinates) {
    // Catmull-Rom with quadratic end neighbours reproduces any quadratic in the grid's
    // coordinates, end intervals included: a wrong weight, node, mapping or extrapolation breaks
    // it. The quadratic stays inside [0, 1], the LUT's range.
    const uint32_t gridSize = 6, size = 40;
    const auto quadratic = [](double u, double w) {
        return glm::dvec2(0.2 + 0.3 * u - 0.2 * u * w + 0.1 * w * w, 0.5 + 0.3 * u * u - 0.4 * w);
    };
    const auto lut = resampleBrdfLutGrid<double>(gridOf(gridSize, quadratic), gridSize, size);
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const auto at = gridCoordinates((x + 0.5) / size, (y + 0.5) / size);
            const auto expected = quadratic(at.x, at.y);
            ASSERT_NEAR(lut[(y * size + x) * 2], expected.x, 1e-12) << x << " " << y;
            ASSERT_NEAR(lut[(y * size + x) * 2 + 1], expected.y, 1e-12) << x << " " << y;
        }
}

TEST(LutGrid, InterpolationStaysInsideTheLutsRange) {
    // An overshoot past 1 or an undershoot below 0 (which RG16F would store as a negative half)
    // is clamped: Catmull-Rom through a step from 0 to 1 dips below 0 just before it and rises
    // past 1 just after, so a clamped LUT reaches both ends exactly.
    const uint32_t gridSize = 8, size = 64;
    const auto step = [](double u, double) {
        const double value = u > 0.5 ? 1.0 : 0.0;
        return glm::dvec2(value, 1 - value);
    };
    const auto lut = resampleBrdfLutGrid<double>(gridOf(gridSize, step), gridSize, size);
    EXPECT_EQ(*std::min_element(lut.begin(), lut.end()), 0.0);
    EXPECT_EQ(*std::max_element(lut.begin(), lut.end()), 1.0);
}

TEST(LutGrid, ErrorFallsWithTheGridToTheRg32fTarget) {
    // 128² against the converged LUT, in double: measured 2.5e-3 at a 32² grid and 6.8e-6 at
    // 192² (the bake's default), the largest error at the grazing column of low roughness, where
    // the LUT turns over N.V ~ roughness² / 2 (bounds twice those). A finer grid must be far better.
    const auto converged = convergedBrdfLut(128);
    const auto coarse = largestDifference(resampleBrdfLutGrid<double>(brdfLutGridNodes<double>(32, 7), 32, 128), converged);
    const auto fine = largestDifference(resampleBrdfLutGrid<double>(brdfLutGridNodes<double>(192, 7), 192, 128), converged);
    EXPECT_LE(coarse, 5e-3);
    EXPECT_LE(fine, 1.4e-5);
    EXPECT_GT(coarse, 10 * fine);
}

TEST(LutGrid, FloatFollowsDouble) {
    // The shaders' arithmetic: measured 3.0e-6 from double at a 64² grid and a 128² LUT (bound twice).
    const auto nodesFloat = brdfLutGridNodes<float>(64, 7);
    const auto nodesDouble = brdfLutGridNodes<double>(64, 7);
    EXPECT_LE(largestDifference(resampleBrdfLutGrid<float>(nodesFloat, 64, 128),
                                resampleBrdfLutGrid<double>(nodesDouble, 64, 128)),
              6e-6);
}

TEST(LutGrid, RefusesGridsTooSmallToInterpolate) {
    const auto grid = brdfLutGridNodes<double>(3, 7);
    EXPECT_THROW(resampleBrdfLutGrid<double>(grid, 3, 16), std::invalid_argument);
    EXPECT_THROW(resampleBrdfLutGrid<double>(grid, 4, 16), std::invalid_argument); // size mismatch
}

} // namespace
} // namespace iblkit::reference
