#pragma once

// hlsl/SkyCubeCS.hlsl's built-in environment, function by function: T = float follows the
// shader, T = double gives the exact values.

#include "cube_geometry.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace iblkit::reference {

template <typename T>
vec3<T> SkyRadiance(vec3<T> d) {
    const vec3<T> zenith(T(0.18), T(0.36), T(0.95)), horizon(T(1.05), T(1.1), T(1.2));
    return glm::mix(horizon, zenith, std::pow(std::clamp(d.y, T(0), T(1)), T(0.4)));
}

template <typename T>
vec3<T> GroundRadiance(vec3<T> d) {
    const T pi = T(3.14159265358979323846);
    const T longitude = std::atan2(d.x, -d.z), latitude = std::asin(std::clamp(d.y, T(-1), T(1)));
    const int cell = int(std::floor(longitude / (pi / T(12)))) + int(std::floor(latitude / (pi / T(24))));
    const vec3<T> ground = (cell & 1) ? vec3<T>(T(0.42), T(0.36), T(0.28)) : vec3<T>(T(0.16), T(0.14), T(0.12));
    return glm::mix(ground, vec3<T>(T(0.9), T(0.92), T(0.95)), std::exp(d.y * T(40)));
}

template <typename T>
vec3<T> SunRadiance(vec3<T> d) {
    const T pi = T(3.14159265358979323846);
    const vec3<T> sun = glm::normalize(vec3<T>(T(0.3), T(0.45), T(0.84)));
    const T angle = std::atan2(glm::length(glm::cross(d, sun)), glm::dot(d, sun));
    const T radius = T(2.5) * pi / T(180), edge = T(0.1) * pi / T(180);
    const T disc = std::clamp((radius + edge - angle) / (T(2) * edge), T(0), T(1));
    return vec3<T>(T(1), T(0.92), T(0.8)) * (T(4000) * disc + T(40) * std::exp(-angle * T(25)));
}

template <typename T>
vec3<T> EnvironmentRadiance(vec3<T> d) {
    return (d.y >= T(0) ? SkyRadiance(d) : GroundRadiance(d)) + SunRadiance(d);
}

// SkyCubeCS over a size x size cube with supersample² evaluations per texel: RGBA (alpha 1),
// face, row, column.
template <typename T>
std::vector<T> skyCube(uint32_t size, uint32_t supersample) {
    std::vector<T> texels(size_t(size) * size * 6 * 4);
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x) {
                vec3<T> sum(0);
                for (uint32_t j = 0; j < supersample; ++j)
                    for (uint32_t i = 0; i < supersample; ++i) {
                        const vec2<T> at = vec2<T>(T(x), T(y)) + (vec2<T>(T(i), T(j)) + T(0.5)) / T(supersample);
                        sum += EnvironmentRadiance(CubeFaceDirection<T>(face, at / T(size)));
                    }
                sum /= T(supersample * supersample);
                const size_t i = ((size_t(face) * size + y) * size + x) * 4;
                texels[i] = sum.x, texels[i + 1] = sum.y, texels[i + 2] = sum.z, texels[i + 3] = T(1);
            }
    return texels;
}

} // namespace iblkit::reference
