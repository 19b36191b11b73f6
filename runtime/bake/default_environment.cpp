#include "default_environment.hpp"

#include <glm/geometric.hpp>
#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>
#include <vector>

namespace iblkit::bake {
namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec3 sunDirection() { return glm::normalize(glm::dvec3(0.3, 0.45, 0.84)); }

glm::dvec3 skyRadiance(glm::dvec3 d) {
    const glm::dvec3 zenith(0.18, 0.36, 0.95), horizon(1.05, 1.1, 1.2);
    return glm::mix(horizon, zenith, std::pow(std::clamp(d.y, 0.0, 1.0), 0.4));
}

glm::dvec3 groundRadiance(glm::dvec3 d) {
    const double longitude = std::atan2(d.x, -d.z), latitude = std::asin(std::clamp(d.y, -1.0, 1.0));
    const int cell = int(std::floor(longitude / (kPi / 12))) + int(std::floor(latitude / (kPi / 24)));
    const glm::dvec3 light(0.42, 0.36, 0.28), dark(0.16, 0.14, 0.12);
    const glm::dvec3 ground = (cell & 1) ? light : dark;
    // A hazy band just below the horizon joins the ground to the sky.
    return glm::mix(ground, glm::dvec3(0.9, 0.92, 0.95), std::exp(d.y * 40.0));
}

glm::dvec3 sunRadiance(glm::dvec3 d) {
    const double angle = std::acos(std::clamp(glm::dot(d, sunDirection()), -1.0, 1.0));
    const double radius = 2.5 * kPi / 180, edge = 0.1 * kPi / 180;
    const double disc = std::clamp((radius + edge - angle) / (2 * edge), 0.0, 1.0);
    const glm::dvec3 color(1.0, 0.92, 0.8);
    return color * (4000.0 * disc + 40.0 * std::exp(-angle * 25.0));
}

glm::dvec3 panoramaDirection(double u, double v) {
    const double longitude = (u - 0.5) * 2 * kPi, latitude = v * kPi;
    return {std::sin(latitude) * std::sin(longitude), std::cos(latitude), -std::sin(latitude) * std::cos(longitude)};
}

void fillRows(image_io::FloatImage& image, uint32_t firstRow, uint32_t rowStep) {
    constexpr int kSubsamples = 2;
    for (uint32_t row = firstRow; row < image.height; row += rowStep)
        for (uint32_t column = 0; column < image.width; ++column) {
            glm::dvec3 sum(0);
            for (int j = 0; j < kSubsamples; ++j)
                for (int i = 0; i < kSubsamples; ++i)
                    sum += defaultEnvironmentRadiance(panoramaDirection((column + (i + 0.5) / kSubsamples) / image.width,
                                                                        (row + (j + 0.5) / kSubsamples) / image.height));
            sum /= double(kSubsamples * kSubsamples);
            float* texel = &image.values[(size_t(row) * image.width + column) * 3];
            texel[0] = float(sum.r), texel[1] = float(sum.g), texel[2] = float(sum.b);
        }
}

} // namespace

glm::dvec3 defaultEnvironmentRadiance(glm::dvec3 direction) {
    const glm::dvec3 d = glm::normalize(direction);
    return (d.y >= 0 ? skyRadiance(d) : groundRadiance(d)) + sunRadiance(d);
}

image_io::FloatImage defaultEnvironmentPanorama(uint32_t width) {
    image_io::FloatImage image{width, width / 2, 3, std::vector<float>(size_t(width) * (width / 2) * 3)};
    const uint32_t threads = std::max(1u, std::thread::hardware_concurrency());
    {
        std::vector<std::jthread> workers; // joined at the end of this block, before the image is returned
        for (uint32_t worker = 0; worker < threads; ++worker)
            workers.emplace_back(fillRows, std::ref(image), worker, threads);
    }
    return image;
}

} // namespace iblkit::bake
