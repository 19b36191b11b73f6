#include "reference_irradiance.hpp"

#include "cube_environment.hpp"
#include "cube_geometry.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <thread>

namespace iblkit::reference {
namespace {

double areaElement(double x, double y) { return std::atan2(x * y, std::sqrt(x * x + y * y + 1)); }

glm::dvec3 texelRadiance(std::span<const float> texels, size_t texel) {
    return {texels[texel * 4], texels[texel * 4 + 1], texels[texel * 4 + 2]};
}

// ∫ n·l dω over the part of a spherical polygon (great-circle edges between `corners`) above
// n's horizon: the polygon clipped by the plane n·x = 0 (a point of an edge's plane, normalised,
// lies on its arc), then Lambert's formula.
double clippedPolygonCosine(const glm::dvec3& n, const std::array<glm::dvec3, 4>& corners) {
    std::array<glm::dvec3, 8> clipped;
    size_t count = 0;
    for (size_t i = 0; i < 4; ++i) {
        const glm::dvec3 &a = corners[i], &b = corners[(i + 1) % 4];
        const double da = glm::dot(n, a), db = glm::dot(n, b);
        if (da >= 0) clipped[count++] = a;
        if ((da >= 0) != (db >= 0)) clipped[count++] = glm::normalize(a + (b - a) * (da / (da - db)));
    }
    double sum = 0;
    for (size_t i = 0; i < count; ++i) {
        const glm::dvec3 &a = clipped[i], &b = clipped[(i + 1) % count];
        const glm::dvec3 edge = glm::cross(a, b);
        const double length = glm::length(edge);
        if (length < 1e-300) continue;
        sum += std::atan2(length, glm::dot(a, b)) * glm::dot(n, edge / length);
    }
    return std::abs(sum) / 2;
}

// ∫ l dω over a spherical polygon (Lambert's vector form): ½ Σ angle_i unit(v_i × v_(i+1)),
// pointing out through the polygon.
glm::dvec3 polygonVector(const std::array<glm::dvec3, 4>& corners, const glm::dvec3& centre) {
    glm::dvec3 sum(0);
    for (size_t i = 0; i < 4; ++i) {
        const glm::dvec3 &a = corners[i], &b = corners[(i + 1) % 4];
        const glm::dvec3 edge = glm::cross(a, b);
        sum += std::atan2(glm::length(edge), glm::dot(a, b)) * glm::normalize(edge);
    }
    return glm::dot(sum, centre) < 0 ? -sum / 2.0 : sum / 2.0;
}

struct IrradianceTexel {
    glm::dvec3 centre, radiance;
    glm::dvec3 vector; // ∫ l dω over the texel: n·vector is its cosine integral when it is all above n's horizon
    std::array<glm::dvec3, 4> corners;
    double reach; // sine of the largest angle from the centre to a corner
};

std::vector<IrradianceTexel> sourceTexels(std::span<const CubeTexelRadiance> texels, uint32_t size) {
    std::vector<IrradianceTexel> result;
    for (const auto& texel : texels) {
        const uint32_t face = texel.index / (size * size), row = texel.index / size % size, column = texel.index % size;
        IrradianceTexel t;
        t.radiance = glm::dvec3(texel.radiance);
        t.centre = cubeTexelCentre(face, column, row, size);
        double reach = 0;
        for (int corner = 0; corner < 4; ++corner) {
            const double u = double(column + (corner == 1 || corner == 2)) / size;
            const double v = double(row + (corner >= 2)) / size;
            t.corners[size_t(corner)] = CubeFaceDirection<double>(face, glm::dvec2(u, v));
            reach = std::max(reach, glm::length(glm::cross(t.centre, t.corners[size_t(corner)])));
        }
        t.reach = reach;
        t.vector = polygonVector(t.corners, t.centre);
        result.push_back(t);
    }
    return result;
}

template <typename Fill>
void forEachOutputTexel(size_t count, const Fill& fill) {
    const size_t threads = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::jthread> workers;
    for (size_t worker = 0; worker < threads; ++worker)
        workers.emplace_back([&, worker] {
            for (size_t out = worker; out < count; out += threads) fill(out);
        });
}

} // namespace

glm::dvec3 cubeTexelCentre(uint32_t face, uint32_t column, uint32_t row, uint32_t size) {
    return glm::normalize(cubeTexelDirection(face, column, row, size));
}

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
                const auto basis = shBasis(cubeTexelCentre(face, column, row, size));
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
                directions.push_back(cubeTexelCentre(face, column, row, size));
                weighted.push_back(texelRadiance(texels, texel) * cubeTexelSolidAngle(column, row, size));
            }
    std::vector<glm::dvec3> result(size_t(6) * outSize * outSize);
    const auto fill = [&](size_t first, size_t step) {
        for (size_t out = first; out < result.size(); out += step) {
            const uint32_t face = uint32_t(out / (size_t(outSize) * outSize));
            const uint32_t row = uint32_t(out / outSize % outSize), column = uint32_t(out % outSize);
            const glm::dvec3 normal = cubeTexelCentre(face, column, row, outSize);
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

std::vector<float> irradianceMoments(std::span<const float> texels, uint32_t size, uint32_t momentSize) {
    const uint32_t ratio = size / momentSize;
    std::vector<double> solidAngles(size_t(size) * size); // the same on every face
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) solidAngles[size_t(y) * size + x] = cubeTexelSolidAngle(x, y, size);
    std::vector<float> moments(size_t(6) * momentSize * momentSize * 8, 0.f);
    forEachOutputTexel(size_t(6) * momentSize * momentSize, [&](size_t out) {
        const uint32_t face = uint32_t(out / (size_t(momentSize) * momentSize));
        const uint32_t row = uint32_t(out / momentSize % momentSize), column = uint32_t(out % momentSize);
        glm::dvec3 energy(0), direction(0);
        double weight = 0;
        for (uint32_t y = row * ratio; y < (row + 1) * ratio; ++y)
            for (uint32_t x = column * ratio; x < (column + 1) * ratio; ++x) {
                const double solidAngle = solidAngles[size_t(y) * size + x];
                const glm::dvec3 radiance = texelRadiance(texels, (size_t(face) * size + y) * size + x) * solidAngle;
                const double luminance = 0.2126 * radiance.r + 0.7152 * radiance.g + 0.0722 * radiance.b;
                energy += radiance;
                direction += luminance * cubeTexelCentre(face, x, y, size);
                weight += luminance;
            }
        if (weight > 0) direction /= weight;
        else direction = glm::dvec3(0);
        float* at = &moments[out * 8];
        for (int axis = 0; axis < 3; ++axis) {
            at[axis] = float(energy[axis]);
            at[4 + axis] = float(direction[axis]);
        }
    });
    return moments;
}

std::vector<glm::dvec3> irradianceFromMoments(const std::vector<float>& moments, uint32_t momentSize, uint32_t outSize) {
    const size_t texels = size_t(6) * momentSize * momentSize;
    std::vector<glm::dvec3> result(size_t(6) * outSize * outSize);
    forEachOutputTexel(result.size(), [&](size_t out) {
        const uint32_t face = uint32_t(out / (size_t(outSize) * outSize));
        const glm::dvec3 n = cubeTexelCentre(face, uint32_t(out % outSize), uint32_t(out / outSize % outSize), outSize);
        glm::dvec3 sum(0);
        for (size_t t = 0; t < texels; ++t) {
            const float* m = &moments[t * 8];
            sum += glm::dvec3(m[0], m[1], m[2]) * std::max(0.0, glm::dot(n, glm::dvec3(m[4], m[5], m[6])));
        }
        result[out] = sum / std::numbers::pi;
    });
    return result;
}

glm::dvec3 shIrradiance(const std::array<glm::dvec3, 9>& radiance, glm::dvec3 normal) {
    const auto basis = shBasis(glm::normalize(normal));
    glm::dvec3 sum(0);
    for (size_t k = 0; k < 9; ++k) sum += radiance[k] * basis[k] * (k == 0 ? 1.0 : k < 4 ? 2.0 / 3.0 : 0.25);
    return sum;
}

std::vector<CubeTexelRadiance> litTexels(const std::vector<float>& texels) {
    std::vector<CubeTexelRadiance> lit;
    for (size_t texel = 0; texel < texels.size() / 4; ++texel) {
        const glm::vec3 radiance(texels[4 * texel], texels[4 * texel + 1], texels[4 * texel + 2]);
        if (radiance != glm::vec3(0)) lit.push_back({uint32_t(texel), radiance});
    }
    return lit;
}

std::vector<glm::dvec3> exactIrradianceCube(const std::vector<float>& texels, uint32_t size, uint32_t outSize) {
    return exactIrradianceCube(litTexels(texels), size, outSize);
}

std::vector<glm::dvec3> exactIrradianceCube(std::span<const CubeTexelRadiance> texels, uint32_t size, uint32_t outSize) {
    const auto sources = sourceTexels(texels, size);
    std::vector<glm::dvec3> result(size_t(6) * outSize * outSize);
    // Outputs in blocks, each source texel read once a block rather than once an output: the
    // sources outgrow the caches (170 bytes each, 6 · 256² of them), and reading them was the
    // time. Each output still sums its sources in their order.
    constexpr size_t kBlock = 16;
    forEachOutputTexel((result.size() + kBlock - 1) / kBlock, [&](size_t block) {
        const size_t first = block * kBlock, count = std::min(kBlock, result.size() - first);
        std::array<glm::dvec3, kBlock> normals, sums;
        for (size_t i = 0; i < count; ++i) {
            const size_t out = first + i;
            const uint32_t face = uint32_t(out / (size_t(outSize) * outSize));
            normals[i] = cubeTexelCentre(face, uint32_t(out % outSize), uint32_t(out / outSize % outSize), outSize);
            sums[i] = glm::dvec3(0);
        }
        for (const auto& t : sources)
            for (size_t i = 0; i < count; ++i) {
                const glm::dvec3& n = normals[i];
                const double cosine = glm::dot(n, t.centre);
                if (cosine > t.reach) sums[i] += t.radiance * glm::dot(n, t.vector);
                else if (cosine > -t.reach) sums[i] += t.radiance * clippedPolygonCosine(n, t.corners);
            }
        for (size_t i = 0; i < count; ++i) result[first + i] = sums[i] / std::numbers::pi;
    });
    return result;
}

} // namespace iblkit::reference
