#include "cube_environment.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace iblkit::reference {
namespace {

struct FaceCoordinates {
    uint32_t face;
    double s, t; // in [0, 1] on the face
};

// The Vulkan specification's "Cube Map Face Selection" table.
FaceCoordinates selectFace(glm::dvec3 d) {
    const glm::dvec3 m = glm::abs(d);
    if (m.x >= m.y && m.x >= m.z)
        return d.x >= 0 ? FaceCoordinates{0, 0.5 * (-d.z / m.x + 1), 0.5 * (-d.y / m.x + 1)}
                        : FaceCoordinates{1, 0.5 * (d.z / m.x + 1), 0.5 * (-d.y / m.x + 1)};
    if (m.y >= m.z)
        return d.y >= 0 ? FaceCoordinates{2, 0.5 * (d.x / m.y + 1), 0.5 * (d.z / m.y + 1)}
                        : FaceCoordinates{3, 0.5 * (d.x / m.y + 1), 0.5 * (-d.z / m.y + 1)};
    return d.z >= 0 ? FaceCoordinates{4, 0.5 * (d.x / m.z + 1), 0.5 * (-d.y / m.z + 1)}
                    : FaceCoordinates{5, 0.5 * (-d.x / m.z + 1), 0.5 * (-d.y / m.z + 1)};
}

} // namespace

glm::dvec3 cubeTexelDirection(uint32_t face, double column, double row, uint32_t size) {
    const double a = 2 * (column + 0.5) / size - 1, b = 2 * (row + 0.5) / size - 1;
    switch (face) {
    case 0: return {1, -b, -a};
    case 1: return {-1, -b, a};
    case 2: return {a, 1, b};
    case 3: return {a, -1, -b};
    case 4: return {a, -b, 1};
    default: return {-a, -b, -1};
    }
}

CubeTexelIndex cubeTexelOf(glm::dvec3 direction, uint32_t size) {
    const auto coordinates = selectFace(direction);
    const int n = static_cast<int>(size);
    return {coordinates.face, uint32_t(std::clamp(static_cast<int>(std::floor(coordinates.s * n)), 0, n - 1)),
            uint32_t(std::clamp(static_cast<int>(std::floor(coordinates.t * n)), 0, n - 1))};
}

CubeEnvironment::CubeEnvironment(uint32_t size, std::vector<float> texels) : size_(size), texels_(std::move(texels)) {
    if (texels_.size() != size_t(6) * size * size * 4) throw std::invalid_argument("cube texels do not match the size");
}

glm::dvec3 CubeEnvironment::testRadiance(glm::dvec3 d) {
    d = glm::normalize(d);
    const double up = d.y;
    const glm::dvec3 zenith(0.25, 0.45, 0.9), horizon(0.8, 0.85, 0.9), ground(0.3, 0.22, 0.15);
    const double skyBlend = std::clamp(up * 4.0, 0.0, 1.0);
    glm::dvec3 color = up >= 0 ? glm::mix(horizon, zenith, std::sqrt(skyBlend)) : glm::mix(horizon, ground, std::min(1.0, -up * 6.0));
    color *= 1.0 + 0.2 * std::sin(3.0 * d.x) * std::cos(2.0 * d.z);
    const glm::dvec3 sunDirection = glm::normalize(glm::dvec3(0.5, 0.6, -0.62));
    color += glm::dvec3(40.0, 36.0, 30.0) * std::exp(-30.0 * (1.0 - glm::dot(d, sunDirection)));
    return color;
}

CubeEnvironment CubeEnvironment::testEnvironment(uint32_t size) {
    std::vector<float> texels;
    texels.reserve(size_t(6) * size * size * 4);
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t row = 0; row < size; ++row)
            for (uint32_t column = 0; column < size; ++column) {
                const glm::dvec3 radiance = testRadiance(cubeTexelDirection(face, column, row, size));
                texels.insert(texels.end(), {float(radiance.r), float(radiance.g), float(radiance.b), 1.0f});
            }
    return CubeEnvironment(size, std::move(texels));
}

glm::dvec3 CubeEnvironment::texel(uint32_t face, int column, int row) const {
    const int n = static_cast<int>(size_);
    const bool outsideColumns = column < 0 || column >= n, outsideRows = row < 0 || row >= n;
    if (outsideColumns && outsideRows) {
        // Beyond a corner no face has the texel: the mean of the three around the corner, as
        // llvmpipe reads it (taking one of the three put a single read 4 % off at a corner).
        const int edgeColumn = std::clamp(column, 0, n - 1), edgeRow = std::clamp(row, 0, n - 1);
        return (texel(face, edgeColumn, edgeRow) + texel(face, column, edgeRow) + texel(face, edgeColumn, row)) / 3.0;
    }
    if (outsideColumns || outsideRows) {
        // Beyond an edge: the texel of the neighbouring face that the extrapolated direction
        // reaches, as seamless cube filtering reads it.
        const auto other = cubeTexelOf(cubeTexelDirection(face, column, row, size_), size_);
        face = other.face;
        column = static_cast<int>(other.column);
        row = static_cast<int>(other.row);
    }
    const size_t at = ((size_t(face) * size_ + row) * size_ + column) * 4;
    return {texels_[at], texels_[at + 1], texels_[at + 2]};
}

glm::dvec3 CubeEnvironment::sample(glm::dvec3 direction) const {
    const auto coordinates = selectFace(direction);
    const double u = coordinates.s * size_ - 0.5, v = coordinates.t * size_ - 0.5;
    const double column = std::floor(u), row = std::floor(v);
    const double alpha = u - column, beta = v - row;
    const int i = static_cast<int>(column), j = static_cast<int>(row);
    const auto f = coordinates.face;
    return (1 - alpha) * (1 - beta) * texel(f, i, j) + alpha * (1 - beta) * texel(f, i + 1, j) +
           (1 - alpha) * beta * texel(f, i, j + 1) + alpha * beta * texel(f, i + 1, j + 1);
}

} // namespace iblkit::reference
