#include "reference_irradiance.hpp"

#include "cube_environment.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <thread>

namespace iblkit::reference {
namespace {

double areaElement(double x, double y) { return std::atan2(x * y, std::sqrt(x * x + y * y + 1)); }

glm::dvec3 texelRadiance(const std::vector<float>& texels, size_t texel) {
    return {texels[texel * 4], texels[texel * 4 + 1], texels[texel * 4 + 2]};
}

glm::dvec3 texelCentre(uint32_t face, uint32_t column, uint32_t row, uint32_t size) {
    return glm::normalize(cubeTexelDirection(face, column, row, size));
}

} // namespace

double cubeTexelSolidAngle(uint32_t column, uint32_t row, uint32_t size) {
    const double x0 = 2.0 * column / size - 1, y0 = 2.0 * row / size - 1;
    const double x1 = x0 + 2.0 / size, y1 = y0 + 2.0 / size;
    return areaElement(x0, y0) - areaElement(x0, y1) - areaElement(x1, y0) + areaElement(x1, y1);
}

std::vector<float> downsampleCube(const std::vector<float>& texels, uint32_t size) {
    const uint32_t half = size / 2;
    std::vector<float> result(size_t(6) * half * half * 4);
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t row = 0; row < half; ++row)
            for (uint32_t column = 0; column < half; ++column)
                for (uint32_t c = 0; c < 4; ++c) {
                    double sum = 0;
                    for (uint32_t j = 0; j < 2; ++j)
                        for (uint32_t i = 0; i < 2; ++i)
                            sum += texels[((size_t(face) * size + 2 * row + j) * size + 2 * column + i) * 4 + c];
                    result[((size_t(face) * half + row) * half + column) * 4 + c] = float(sum / 4);
                }
    return result;
}

std::array<glm::dvec3, 9> projectOnSh(const std::vector<float>& texels, uint32_t size) {
    std::array<glm::dvec3, 9> coefficients{};
    size_t texel = 0;
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t row = 0; row < size; ++row)
            for (uint32_t column = 0; column < size; ++column, ++texel) {
                const auto basis = shBasis(texelCentre(face, column, row, size));
                const glm::dvec3 weighted = texelRadiance(texels, texel) * cubeTexelSolidAngle(column, row, size);
                for (size_t k = 0; k < 9; ++k) coefficients[k] += weighted * basis[k];
            }
    return coefficients;
}

std::vector<glm::dvec3> irradianceCube(const std::vector<float>& texels, uint32_t size, uint32_t outSize) {
    std::vector<glm::dvec3> directions, weighted;
    size_t texel = 0;
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t row = 0; row < size; ++row)
            for (uint32_t column = 0; column < size; ++column, ++texel) {
                directions.push_back(texelCentre(face, column, row, size));
                weighted.push_back(texelRadiance(texels, texel) * cubeTexelSolidAngle(column, row, size));
            }
    std::vector<glm::dvec3> result(size_t(6) * outSize * outSize);
    const auto fill = [&](size_t first, size_t step) {
        for (size_t out = first; out < result.size(); out += step) {
            const uint32_t face = uint32_t(out / (size_t(outSize) * outSize));
            const uint32_t row = uint32_t(out / outSize % outSize), column = uint32_t(out % outSize);
            const glm::dvec3 normal = texelCentre(face, column, row, outSize);
            glm::dvec3 sum(0);
            for (size_t i = 0; i < directions.size(); ++i) sum += weighted[i] * std::max(0.0, glm::dot(normal, directions[i]));
            result[out] = sum / std::numbers::pi;
        }
    };
    const size_t threads = std::max(1u, std::thread::hardware_concurrency());
    {
        std::vector<std::jthread> workers;
        for (size_t worker = 0; worker < threads; ++worker) workers.emplace_back(fill, worker, threads);
    }
    return result;
}

glm::dvec3 shIrradiance(const std::array<glm::dvec3, 9>& radiance, glm::dvec3 normal) {
    const auto basis = shBasis(glm::normalize(normal));
    glm::dvec3 sum(0);
    for (size_t k = 0; k < 9; ++k) sum += radiance[k] * basis[k] * (k == 0 ? 1.0 : k < 4 ? 2.0 / 3.0 : 0.25);
    return sum;
}

} // namespace iblkit::reference
