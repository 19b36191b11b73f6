#include "environment_cases.hpp"

#include "bench_environments.hpp"
#include "cube_environment.hpp"
#include "environment_input.hpp"
#include "suite_inputs.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

namespace iblkit::stress {
namespace {

using consistency::Panorama;
using consistency::SuiteEnvironment;

// Cube.fxh's EquirectToDirection at a point of the panorama (u, v in [0, 1], v = 0 at the zenith).
glm::dvec3 panoramaDirection(double u, double v) {
    const double longitude = (u - 0.5) * 2 * std::numbers::pi, latitude = v * std::numbers::pi;
    return {std::sin(latitude) * std::sin(longitude), std::cos(latitude), -std::sin(latitude) * std::cos(longitude)};
}

const glm::dvec3 kSunDirection = glm::normalize(glm::dvec3(0.3, 0.8, 0.5));

std::vector<float> filled(size_t texels, float value) {
    std::vector<float> values(texels * 4, value);
    for (size_t t = 0; t < texels; ++t) values[t * 4 + 3] = 1.f;
    return values;
}

Panorama constantPanorama(uint32_t width, float value) {
    return {width, width / 2, filled(size_t(width) * (width / 2), value)};
}

// Each source texel's radiance, weighted by its solid angle, into the target texel its centre
// falls in; the target texels are the weighted means.
struct AreaAverage {
    std::vector<double> sums, weights;
    explicit AreaAverage(size_t texels) : sums(texels * 3), weights(texels) {}
    void add(size_t target, const float* rgb, double weight) {
        for (int c = 0; c < 3; ++c) sums[target * 3 + c] += weight * rgb[c];
        weights[target] += weight;
    }
    std::vector<float> rgba() const {
        std::vector<float> values;
        for (size_t t = 0; t < weights.size(); ++t)
            for (int c = 0; c < 4; ++c)
                values.push_back(c == 3 ? 1.f : weights[t] > 0 ? float(sums[t * 3 + c] / weights[t]) : 0.f);
        return values;
    }
};

template <typename Visit>
void forEachTexel(const image_io::FloatImage& image, Visit visit) {
    const auto rgba = image_io::rgbaValues(image);
    for (uint32_t y = 0; y < image.height; ++y) {
        const double v = (y + 0.5) / image.height;
        for (uint32_t x = 0; x < image.width; ++x)
            visit(x, y, panoramaDirection((x + 0.5) / image.width, v), &rgba[(size_t(y) * image.width + x) * 4],
                  std::sin(v * std::numbers::pi));
    }
}

} // namespace

SuiteEnvironment constantEnvironment(float value) {
    return {fmt::format("constant {:g}", value), [value](uint32_t size) { return filled(size_t(size) * size * 6, value); },
            [value](uint32_t width) { return constantPanorama(width, value); }};
}

SuiteEnvironment sunEnvironment(float value) {
    const auto cube = [value](uint32_t size) {
        auto texels = filled(size_t(size) * size * 6, 1.f);
        const auto sun = reference::cubeTexelOf(kSunDirection, size);
        const size_t at = (size_t(sun.face) * size + sun.row) * size + sun.column;
        std::fill_n(texels.begin() + at * 4, 3, value);
        return texels;
    };
    const auto panorama = [value](uint32_t width) {
        auto result = constantPanorama(width, 1.f);
        const double longitude = std::atan2(kSunDirection.x, -kSunDirection.z), latitude = std::acos(kSunDirection.y);
        const auto x = std::min(width - 1, uint32_t((longitude / (2 * std::numbers::pi) + 0.5) * width));
        const auto y = std::min(result.height - 1, uint32_t(latitude / std::numbers::pi * result.height));
        std::fill_n(result.texels.begin() + (size_t(y) * width + x) * 4, 3, value);
        return result;
    };
    return {fmt::format("one-texel sun of {:g} on 1", value), cube, panorama};
}

SuiteEnvironment panoramaEnvironment(const std::filesystem::path& path, const std::string& name) {
    const auto image = std::make_shared<image_io::FloatImage>(bake::loadEnvironment(path, {}).panorama);
    const auto cube = [image](uint32_t size) {
        AreaAverage average(size_t(size) * size * 6);
        forEachTexel(*image, [&](uint32_t, uint32_t, glm::dvec3 direction, const float* rgb, double weight) {
            const auto texel = reference::cubeTexelOf(direction, size);
            average.add((size_t(texel.face) * size + texel.row) * size + texel.column, rgb, weight);
        });
        return average.rgba();
    };
    const auto panorama = [image](uint32_t width) {
        const uint32_t height = width / 2;
        AreaAverage average(size_t(width) * height);
        forEachTexel(*image, [&](uint32_t x, uint32_t y, glm::dvec3, const float* rgb, double weight) {
            average.add(size_t(y) * height / image->height * width + size_t(x) * width / image->width, rgb, weight);
        });
        return Panorama{width, height, average.rgba()};
    };
    return {name, cube, panorama};
}

std::vector<EnvironmentCase> environmentCases(bool reduced, const std::filesystem::path& blenderWorlds) {
    std::vector<EnvironmentCase> cases{{constantEnvironment(0.f)}, {constantEnvironment(1.f)},
                                       {constantEnvironment(1e-30f)}, {constantEnvironment(6e4f)}};
    for (const float sun : {1e3f, 1e5f, 1e8f})
        if (!reduced || sun == 1e8f) cases.push_back({sunEnvironment(sun)});
    for (const uint32_t size : {1u, 2u, 4u})
        if (!reduced || size < 4) cases.push_back({consistency::testSuiteEnvironment(), size});
    if (!blenderWorlds.empty())
        for (const char* world : bench::kBlenderWorlds)
            cases.push_back({panoramaEnvironment(blenderWorlds / (std::string(world) + ".exr"), world)});
    return cases;
}

} // namespace iblkit::stress
