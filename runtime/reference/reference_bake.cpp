#include "reference_bake.hpp"

#include "pbr.hpp"

#include <algorithm>
#include <atomic>
#include <thread>

namespace iblkit::reference {
namespace {

// Runs row(0..rows-1) on every hardware thread.
template <typename Row>
void forEachRow(uint32_t rows, const Row& row) {
    std::atomic<uint32_t> next{0};
    const unsigned workers = std::max(1u, std::min(std::thread::hardware_concurrency(), rows));
    std::vector<std::jthread> threads;
    for (unsigned w = 0; w < workers; ++w)
        threads.emplace_back([&] {
            for (uint32_t r = next++; r < rows; r = next++) row(r);
        });
}

} // namespace

template <typename T>
std::vector<T> referenceBrdfLut(uint32_t size, uint32_t sampleCount) {
    std::vector<T> lut(size_t(size) * size * 2);
    forEachRow(size, [&](uint32_t y) {
        for (uint32_t x = 0; x < size; ++x) {
            const vec2<T> uv = (vec2<T>(T(x), T(y)) + T(0.5)) / T(size);
            const vec2<T> scaleBias = IntegrateBRDF<T>(uv.x, uv.y, sampleCount);
            lut[(size_t(y) * size + x) * 2] = scaleBias.x;
            lut[(size_t(y) * size + x) * 2 + 1] = scaleBias.y;
        }
    });
    return lut;
}

template <typename T>
std::vector<T> referencePrefilter(const CubeEnvironment& environment, T roughness, uint32_t size, uint32_t sampleCount) {
    std::vector<T> faces(size_t(6) * size * size * 4);
    const auto envMap = [&](vec3<T> direction) { return vec3<T>(environment.sample(glm::dvec3(direction))); };
    forEachRow(6 * size, [&](uint32_t faceRow) {
        const uint32_t face = faceRow / size, y = faceRow % size;
        for (uint32_t x = 0; x < size; ++x) {
            const vec3<T> normal = PrefilterFaceDirection<T>(face, x, y, size);
            const vec3<T> color = PrefilterSpecular<T>(normal, roughness, envMap, sampleCount);
            const size_t at = ((size_t(face) * size + y) * size + x) * 4;
            faces[at] = color.r;
            faces[at + 1] = color.g;
            faces[at + 2] = color.b;
            faces[at + 3] = T(0);
        }
    });
    return faces;
}

template std::vector<float> referenceBrdfLut<float>(uint32_t, uint32_t);
template std::vector<double> referenceBrdfLut<double>(uint32_t, uint32_t);
template std::vector<float> referencePrefilter<float>(const CubeEnvironment&, float, uint32_t, uint32_t);
template std::vector<double> referencePrefilter<double>(const CubeEnvironment&, double, uint32_t, uint32_t);

} // namespace iblkit::reference
