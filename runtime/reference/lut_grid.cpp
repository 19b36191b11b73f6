#include "lut_grid.hpp"

#include "lut_quadrature.hpp"
#include "parallel_rows.hpp"

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace iblkit::reference {
namespace {

template <typename T> using Pair = glm::vec<2, T>;

template <typename T>
T RoughnessGridPosition(T roughness, int last) {
    return std::pow(roughness, T(1) / T(3)) * T(last);
}

template <typename T>
T NdotvGridPosition(T ndotv, int last) {
    return std::pow(ndotv / (T(1) + std::sqrt(T(1) - ndotv)), T(1) / T(3)) * T(last);
}

template <typename T>
T RoughnessGridNodeValue(T w) {
    return w * w * w;
}

template <typename T>
Pair<T> NdotvGridNodeValue(T u) {
    const T s = u * u * u, rest = (T(1) - u) * (T(1) + u + u * u);
    return {s * (T(2) - s), rest * rest};
}

template <typename T>
glm::vec<4, T> CatmullRomWeights(T t) {
    const T t2 = t * t, t3 = t2 * t;
    return T(0.5) * glm::vec<4, T>(-t + T(2) * t2 - t3, T(2) - T(5) * t2 + T(3) * t3, t + T(4) * t2 - T(3) * t3, t3 - t2);
}

template <typename T>
Pair<T> CatmullRom(Pair<T> before, Pair<T> start, Pair<T> end, Pair<T> after, int cell, int last, glm::vec<4, T> weights) {
    if (cell == 0) before = T(3) * start - T(3) * end + after;
    if (cell == last - 1) after = T(3) * end - T(3) * start + before;
    return weights.x * before + weights.y * start + weights.z * end + weights.w * after;
}

template <typename T>
Pair<T> RowInterpolation(std::span<const T> grid, int row, int cell, int last, glm::vec<4, T> weights) {
    const auto node = [&](int i) {
        const size_t at = (size_t(row) * size_t(last + 1) + size_t(i)) * 2;
        return Pair<T>(grid[at], grid[at + 1]);
    };
    return CatmullRom(node(std::max(cell - 1, 0)), node(cell), node(cell + 1), node(std::min(cell + 2, last)), cell, last,
                      weights);
}

template <typename T>
Pair<T> ResampleTexel(std::span<const T> grid, int last, T ndotv, T roughness) {
    const Pair<T> position(NdotvGridPosition(ndotv, last), RoughnessGridPosition(roughness, last));
    const glm::ivec2 cell(std::min(int(position.x), last - 1), std::min(int(position.y), last - 1));
    const auto across = CatmullRomWeights(position.x - T(cell.x)), down = CatmullRomWeights(position.y - T(cell.y));
    std::array<Pair<T>, 4> rows;
    for (int k = 0; k < 4; ++k) rows[k] = RowInterpolation(grid, std::clamp(cell.y - 1 + k, 0, last), cell.x, last, across);
    return glm::clamp(CatmullRom(rows[0], rows[1], rows[2], rows[3], cell.y, last, down), T(0), T(1));
}

} // namespace

template <typename T>
std::vector<T> brdfLutGridNodes(uint32_t gridSize, uint32_t nodes) {
    if (gridSize < 2) throw std::invalid_argument("a LUT grid needs at least 2 nodes per side");
    std::vector<T> grid(size_t(gridSize) * gridSize * 2);
    forEachRow(gridSize, [&](uint32_t y) {
        const T roughness = RoughnessGridNodeValue(T(y) / T(gridSize - 1));
        for (uint32_t x = 0; x < gridSize; ++x) {
            const auto ndotv = NdotvGridNodeValue(T(x) / T(gridSize - 1));
            const auto scaleBias = IntegrateBrdfQuadrature(ndotv.x, ndotv.y, roughness, nodes);
            grid[(size_t(y) * gridSize + x) * 2] = scaleBias.x;
            grid[(size_t(y) * gridSize + x) * 2 + 1] = scaleBias.y;
        }
    });
    return grid;
}

template <typename T>
std::vector<T> resampleBrdfLutGrid(std::span<const T> grid, uint32_t gridSize, uint32_t size) {
    if (gridSize < 4) throw std::invalid_argument("the LUT grid's interpolation needs at least 4 nodes per side");
    if (grid.size() != size_t(gridSize) * gridSize * 2) throw std::invalid_argument("the LUT grid's size does not match");
    std::vector<T> lut(size_t(size) * size * 2);
    const int last = int(gridSize) - 1;
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const auto value = ResampleTexel(grid, last, (T(x) + T(0.5)) / T(size), (T(y) + T(0.5)) / T(size));
            lut[(size_t(y) * size + x) * 2] = value.x;
            lut[(size_t(y) * size + x) * 2 + 1] = value.y;
        }
    return lut;
}

template std::vector<float> brdfLutGridNodes(uint32_t, uint32_t);
template std::vector<double> brdfLutGridNodes(uint32_t, uint32_t);
template std::vector<float> resampleBrdfLutGrid(std::span<const float>, uint32_t, uint32_t);
template std::vector<double> resampleBrdfLutGrid(std::span<const double>, uint32_t, uint32_t);

} // namespace iblkit::reference
