#pragma once

// hlsl/Common/Cube.fxh's geometry, function by function: T = float follows the shaders,
// T = double gives the exact values.

#include "pbr.hpp"

#include <cmath>
#include <cstdint>

namespace iblkit::reference {

template <typename T>
vec3<T> CubeFacePoint(uint32_t face, vec2<T> uv) {
    uv = (uv - T(0.5)) * vec2<T>(T(2), T(-2));
    switch (face) {
    case 0: return vec3<T>(T(1), uv.y, -uv.x);
    case 1: return vec3<T>(T(-1), uv.y, uv.x);
    case 2: return vec3<T>(uv.x, T(1), -uv.y);
    case 3: return vec3<T>(uv.x, T(-1), uv.y);
    case 4: return vec3<T>(uv.x, uv.y, T(1));
    default: return vec3<T>(-uv.x, uv.y, T(-1));
    }
}

template <typename T>
vec3<T> CubeFaceDirection(uint32_t face, vec2<T> uv) {
    return glm::normalize(CubeFacePoint(face, uv));
}

// The inverse, as Vulkan selects a face (RenderReferenceCS's CubeFaceOf): the face of d's largest
// component (+X before +Y before +Z on ties) and where on it, uv in [0, 1]².
template <typename T>
uint32_t CubeFaceOf(vec3<T> d, vec2<T>& uv) {
    const vec3<T> a = glm::abs(d);
    uint32_t face;
    T major;
    vec2<T> st;
    if (a.x >= a.y && a.x >= a.z) major = a.x, face = d.x >= 0 ? 0 : 1, st = {d.x >= 0 ? -d.z : d.z, -d.y};
    else if (a.y >= a.z) major = a.y, face = d.y >= 0 ? 2 : 3, st = {d.x, d.y >= 0 ? d.z : -d.z};
    else major = a.z, face = d.z >= 0 ? 4 : 5, st = {d.z >= 0 ? d.x : -d.x, -d.y};
    uv = glm::clamp((st / major + T(1)) * T(0.5), T(0), T(1));
    return face;
}

template <typename T>
T CubeAreaElement(T x, T y) {
    return std::atan2(x * y, std::sqrt(x * x + y * y + T(1)));
}

template <typename T>
T CubeTexelSolidAngle(uint32_t column, uint32_t row, uint32_t size) {
    const T inverseSize = T(1) / T(size);
    const T x0 = T(2) * T(column) * inverseSize - T(1), y0 = T(2) * T(row) * inverseSize - T(1);
    const T x1 = x0 + T(2) * inverseSize, y1 = y0 + T(2) * inverseSize;
    return CubeAreaElement(x0, y0) - CubeAreaElement(x0, y1) - CubeAreaElement(x1, y0) + CubeAreaElement(x1, y1);
}

} // namespace iblkit::reference
