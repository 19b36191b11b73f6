#include "reference_bake.hpp"

#include "cube_geometry.hpp"
#include "prefilter_faces.hpp"
#include "reference_irradiance.hpp"

#include <algorithm>
#include <cmath>

namespace iblkit::reference {
namespace {

template <typename T>
vec2<T> DirectionToEquirect(vec3<T> direction) {
    const T longitude = std::atan2(direction.x, -direction.z);
    const T latitude = std::acos(glm::clamp(direction.y, T(-1), T(1)));
    return vec2<T>(T(0.5) + longitude / (T(2) * PI<T>), latitude / PI<T>);
}

// HLSL's lerp as llvmpipe computes it: a + t (b - a).
template <typename T>
vec3<T> lerp(vec3<T> a, vec3<T> b, T t) {
    return a + t * (b - a);
}

size_t texelIndex(uint32_t face, uint32_t row, uint32_t column, uint32_t size) {
    return ((size_t(face) * size + row) * size + column) * 4;
}

glm::vec3 texelRgb(const std::vector<float>& texels, size_t at) { return {texels[at], texels[at + 1], texels[at + 2]}; }

} // namespace

template <typename T>
std::vector<T> referenceBrdfLut(uint32_t size, uint32_t sampleCount) {
    std::vector<T> lut(size_t(size) * size * 2);
    forEachRow(size, [&](uint32_t y) {
        const auto halfVectors = IntegrateBRDFHalfVectors<T>((T(y) + T(0.5)) / T(size), sampleCount);
        for (uint32_t x = 0; x < size; ++x) {
            const vec2<T> uv = (vec2<T>(T(x), T(y)) + T(0.5)) / T(size);
            const vec2<T> scaleBias = IntegrateBRDFOver<T>(uv.x, uv.y, halfVectors);
            lut[(size_t(y) * size + x) * 2] = scaleBias.x;
            lut[(size_t(y) * size + x) * 2 + 1] = scaleBias.y;
        }
    });
    return lut;
}

template <typename T>
std::vector<T> referencePrefilter(const CubeEnvironment& environment, T roughness, uint32_t size, uint32_t sampleCount) {
    const auto envMap = [&](vec3<T> direction) { return vec3<T>(environment.sample(glm::dvec3(direction))); };
    return prefilterFaces<T>(size, [&](vec3<T> normal) { return PrefilterSpecular<T>(normal, roughness, envMap, sampleCount); });
}

template <typename T>
std::vector<T> referenceEquirectToCube(const std::vector<float>& panorama, uint32_t width, uint32_t height, uint32_t size,
                                       uint32_t supersample) {
    const int w = int(width), h = int(height);
    const auto texel = [&](int x, int y) { // EquirectTexel
        x = (x % w + w) % w;
        y = std::clamp(y, 0, h - 1);
        const size_t at = (size_t(y) * width + size_t(x)) * 4;
        return vec3<T>(T(panorama[at]), T(panorama[at + 1]), T(panorama[at + 2]));
    };
    const auto sample = [&](vec3<T> direction) { // SampleEquirect
        const vec2<T> position = DirectionToEquirect(direction) * vec2<T>(T(w), T(h)) - T(0.5);
        const vec2<T> cell = glm::floor(position), f = position - cell;
        const int x = int(cell.x), y = int(cell.y);
        const vec3<T> top = lerp(texel(x, y), texel(x + 1, y), f.x);
        const vec3<T> bottom = lerp(texel(x, y + 1), texel(x + 1, y + 1), f.x);
        return lerp(top, bottom, f.y);
    };
    std::vector<T> cube(size_t(6) * size * size * 4);
    forEachRow(6 * size, [&](uint32_t faceRow) {
        const uint32_t face = faceRow / size, y = faceRow % size;
        for (uint32_t x = 0; x < size; ++x) {
            vec3<T> sum(0);
            for (uint32_t j = 0; j < supersample; ++j)
                for (uint32_t i = 0; i < supersample; ++i) {
                    const vec2<T> offset = (vec2<T>(T(i), T(j)) + T(0.5)) / T(supersample);
                    sum += sample(CubeFaceDirection<T>(face, (vec2<T>(T(x), T(y)) + offset) / T(size)));
                }
            const vec3<T> color = sum / T(supersample * supersample);
            const size_t at = texelIndex(face, y, x, size);
            cube[at] = color.r;
            cube[at + 1] = color.g;
            cube[at + 2] = color.b;
            cube[at + 3] = T(1);
        }
    });
    return cube;
}

std::vector<float> downsampleCubeInFloat(const std::vector<float>& texels, uint32_t size) {
    const uint32_t half = size / 2;
    std::vector<float> result(size_t(6) * half * half * 4);
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t row = 0; row < half; ++row)
            for (uint32_t column = 0; column < half; ++column)
                for (uint32_t c = 0; c < 4; ++c) {
                    const auto at = [&](uint32_t i, uint32_t j) {
                        return texels[texelIndex(face, 2 * row + j, 2 * column + i, size) + c];
                    };
                    const float sum = at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1);
                    result[texelIndex(face, row, column, half) + c] = sum * 0.25f;
                }
    return result;
}

ShSums projectOnShInFloat(const std::vector<float>& texels, uint32_t size) {
    constexpr uint32_t kGroupSize = 64;
    ShSums sums{};
    const uint32_t groupsPerSide = (size + 7) / 8;
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t group = 0; group < groupsPerSide * groupsPerSide; ++group) {
            std::array<std::array<glm::vec4, 9>, kGroupSize> shared{};
            for (uint32_t thread = 0; thread < kGroupSize; ++thread) {
                const uint32_t x = group % groupsPerSide * 8 + thread % 8, y = group / groupsPerSide * 8 + thread / 8;
                auto basis = shBasis(glm::vec3(0.f, 0.f, 1.f));
                glm::vec3 radiance(0.f);
                float solidAngle = 0.f;
                if (x < size && y < size) {
                    basis = shBasis(CubeFaceDirection<float>(face, (glm::vec2(float(x), float(y)) + 0.5f) / float(size)));
                    solidAngle = CubeTexelSolidAngle<float>(x, y, size);
                    radiance = texelRgb(texels, texelIndex(face, y, x, size));
                }
                for (uint32_t k = 0; k < 9; ++k) shared[thread][k] = glm::vec4(radiance * basis[k] * solidAngle, solidAngle);
            }
            for (uint32_t stride = kGroupSize / 2; stride > 0; stride /= 2)
                for (uint32_t thread = 0; thread < stride; ++thread)
                    for (uint32_t k = 0; k < 9; ++k) shared[thread][k] += shared[thread + stride][k];
            for (uint32_t k = 0; k < 9; ++k) sums.radiance[k] += glm::dvec3(shared[0][k]);
            sums.solidAngle += shared[0][0].w;
        }
    return sums;
}

std::vector<float> irradianceCubeInFloat(const std::vector<float>& moments, uint32_t momentSize, uint32_t outSize) {
    const size_t texels = size_t(6) * momentSize * momentSize;
    std::vector<float> result(size_t(6) * outSize * outSize * 4);
    forEachRow(6 * outSize, [&](uint32_t faceRow) {
        const uint32_t face = faceRow / outSize, y = faceRow % outSize;
        for (uint32_t x = 0; x < outSize; ++x) {
            const auto normal = CubeFaceDirection<float>(face, (glm::vec2(float(x), float(y)) + 0.5f) / float(outSize));
            glm::vec3 sum(0.f);
            for (size_t t = 0; t < texels; ++t) {
                const float* m = &moments[t * 8];
                sum += glm::vec3(m[0], m[1], m[2]) * std::max(glm::dot(normal, glm::vec3(m[4], m[5], m[6])), 0.f);
            }
            const glm::vec3 irradiance = sum / PI<float>;
            const size_t at = texelIndex(face, y, x, outSize);
            result[at] = irradiance.r;
            result[at + 1] = irradiance.g;
            result[at + 2] = irradiance.b;
            result[at + 3] = 1.f;
        }
    });
    return result;
}

template std::vector<float> referenceBrdfLut<float>(uint32_t, uint32_t);
template std::vector<double> referenceBrdfLut<double>(uint32_t, uint32_t);
template std::vector<float> referencePrefilter<float>(const CubeEnvironment&, float, uint32_t, uint32_t);
template std::vector<double> referencePrefilter<double>(const CubeEnvironment&, double, uint32_t, uint32_t);
template std::vector<float> referenceEquirectToCube<float>(const std::vector<float>&, uint32_t, uint32_t, uint32_t, uint32_t);
template std::vector<double> referenceEquirectToCube<double>(const std::vector<float>&, uint32_t, uint32_t, uint32_t, uint32_t);

} // namespace iblkit::reference
