#pragma once

// hlsl/document/Common/PBR.fxh in C++ with GLM, function by function: the same names, argument order,
// constants and order of operations, so that T = float follows the shader's arithmetic and
// T = double gives the ground truth. The face table of PrefilterSpecularCS.hlsl is here too.

#include <glm/glm.hpp>

#include <cstdint>
#include <numbers>
#include <vector>

namespace iblkit::reference {

template <typename T> using vec2 = glm::vec<2, T>;
template <typename T> using vec3 = glm::vec<3, T>;

template <typename T> inline constexpr T PI = std::numbers::pi_v<T>;

template <typename T>
T saturate(T x) {
    return glm::clamp(x, T(0), T(1));
}

template <typename T>
T DistributionGGX(T ndoth, T roughness) {
    const T a = roughness * roughness;
    const T a2 = a * a;
    const T ndoth2 = ndoth * ndoth;
    const T num = a2;
    T denom = (ndoth2 * (a2 - T(1)) + T(1));
    denom = PI<T> * denom * denom;
    return num / denom;
}

template <typename T>
vec3<T> FresnelSchlick(T cosTheta, vec3<T> f0) {
    return f0 + (T(1) - f0) * glm::pow(saturate(T(1) - cosTheta), T(5));
}

template <typename T>
T GeometrySchlickGGXForIBL(T ndotv, T roughness) {
    const T a = roughness;
    const T k = (a * a) / T(2);
    const T num = ndotv;
    const T denom = ndotv * (T(1) - k) + k;
    return num / denom;
}

template <typename T>
T GemoetrySmithForIBL(T ndotl, T ndotv, T roughness) {
    const T ggx1 = GeometrySchlickGGXForIBL(ndotl, roughness);
    const T ggx2 = GeometrySchlickGGXForIBL(ndotv, roughness);
    return ggx1 * ggx2;
}

template <typename T>
T GeometrySmithForIBL(T ndotl, T ndotv, T roughness) {
    return GemoetrySmithForIBL(ndotl, ndotv, roughness);
}

template <typename T>
T VanDerCorput(uint32_t bits) {
    bits = (bits << 16) | (bits >> 16);
    bits = ((bits & 0x55555555u) << 1) | ((bits & 0xAAAAAAAAu) >> 1);
    bits = ((bits & 0x33333333u) << 2) | ((bits & 0xCCCCCCCCu) >> 2);
    bits = ((bits & 0x0F0F0F0Fu) << 4) | ((bits & 0xF0F0F0F0u) >> 4);
    bits = ((bits & 0x00FF00FFu) << 8) | ((bits & 0xFF00FF00u) >> 8);
    return T(bits) * T(2.3283064365386963e-10); // 0x100000000
}

template <typename T>
vec2<T> Hammersley(uint32_t i, uint32_t n) {
    return vec2<T>(T(i) / T(n), VanDerCorput<T>(i));
}

template <typename T>
vec3<T> ImportanceSampleGGX(vec2<T> xi, vec3<T> normal, T roughness) {
    const T a = roughness * roughness;
    const T phi = T(2) * PI<T> * xi.x;
    const T cosTheta = std::sqrt((T(1) - xi.y) / (T(1) + (a * a - T(1)) * xi.y)); // InverseCDF
    const T sinTheta = std::sqrt(T(1) - cosTheta * cosTheta);
    const vec3<T> h(std::cos(phi) * sinTheta, std::sin(phi) * sinTheta, cosTheta);
    vec3<T> up = (std::abs(normal.y) < T(0.999)) ? vec3<T>(0, 1, 0) : vec3<T>(0, 0, 1);
    const vec3<T> right = glm::normalize(glm::cross(up, normal));
    up = glm::normalize(glm::cross(normal, right));
    // mul( h, float3x3( right, up, normal ) ): h times the matrix whose rows are the basis.
    return glm::normalize(h.x * right + h.y * up + h.z * normal);
}

// envMap(direction) -> radiance: the shader's envMap.SampleLevel( envMapSampler, dir, 0 ).rgb.
template <typename T, typename Environment>
vec3<T> PrefilterSpecular(vec3<T> normal, T roughness, const Environment& envMap, uint32_t SampleCount) {
    const vec3<T> viewDirection = normal;
    T totalWeight = T(0);
    vec3<T> prefilteredColor(0);
    for (uint32_t i = 0; i < SampleCount; ++i) {
        const vec2<T> xi = Hammersley<T>(i, SampleCount);
        const vec3<T> halfWay = ImportanceSampleGGX(xi, normal, roughness);
        const vec3<T> toLight = glm::normalize(T(2) * glm::dot(viewDirection, halfWay) * halfWay - viewDirection);
        const T ndotl = saturate(glm::dot(normal, toLight));
        if (ndotl > T(0)) {
            prefilteredColor += envMap(toLight) * ndotl;
            totalWeight += ndotl;
        }
    }
    return prefilteredColor / totalWeight;
}

// The half vectors IntegrateBRDF draws about N = +Z, in its order. They depend on the roughness
// alone, so a LUT's row draws them once for all its texels (referenceBrdfLut).
template <typename T>
std::vector<vec3<T>> IntegrateBRDFHalfVectors(T roughness, uint32_t SampleCount) {
    std::vector<vec3<T>> halfVectors(SampleCount);
    for (uint32_t i = 0; i < SampleCount; ++i)
        halfVectors[i] = ImportanceSampleGGX(Hammersley<T>(i, SampleCount), vec3<T>(0, 0, 1), roughness);
    return halfVectors;
}

// IntegrateBRDF over the half vectors IntegrateBRDFHalfVectors drew at `roughness`.
template <typename T>
vec2<T> IntegrateBRDFOver(T ndotv, T roughness, const std::vector<vec3<T>>& halfVectors) {
    const vec3<T> viewDirection(std::sqrt(T(1) - ndotv * ndotv), T(0), ndotv);
    T a = T(0);
    T b = T(0);
    const auto SampleCount = uint32_t(halfVectors.size());
    for (uint32_t i = 0; i < SampleCount; ++i) {
        const vec3<T>& halfWay = halfVectors[i];
        const vec3<T> toLight = glm::normalize(T(2) * glm::dot(viewDirection, halfWay) * halfWay - viewDirection);
        const T ndotl = saturate(toLight.z);
        const T ndoth = saturate(halfWay.z);
        const T vdoth = saturate(glm::dot(viewDirection, halfWay));
        if (ndotl > T(0)) {
            const T g = GemoetrySmithForIBL(ndotl, ndotv, roughness);
            const T gVis = (g * vdoth) / (ndoth * ndotv);
            const T fc = std::pow(T(1) - vdoth, T(5));
            a += (T(1) - fc) * gVis;
            b += fc * gVis;
        }
    }
    a /= T(SampleCount);
    b /= T(SampleCount);
    return vec2<T>(a, b);
}

template <typename T>
vec2<T> IntegrateBRDF(T ndotv, T roughness, uint32_t SampleCount) {
    return IntegrateBRDFOver(ndotv, roughness, IntegrateBRDFHalfVectors(roughness, SampleCount));
}

// PrefilterSpecularCS.hlsl's face table: the direction of texel center (x, y) of `face` on a
// size x size face (Direct3D 9 cubic environment mapping; the same as Vulkan's).
template <typename T>
vec3<T> PrefilterFaceDirection(uint32_t face, uint32_t x, uint32_t y, uint32_t size) {
    vec2<T> uv = (vec2<T>(T(x), T(y)) + T(0.5)) / T(size);
    uv = (uv - T(0.5)) * vec2<T>(T(2), T(-2));
    vec3<T> normal;
    switch (face) {
    case 0: normal = vec3<T>(T(1), uv.y, -uv.x); break;
    case 1: normal = vec3<T>(T(-1), uv.y, uv.x); break;
    case 2: normal = vec3<T>(uv.x, T(1), -uv.y); break;
    case 3: normal = vec3<T>(uv.x, T(-1), uv.y); break;
    case 4: normal = vec3<T>(uv.x, uv.y, T(1)); break;
    default: normal = vec3<T>(-uv.x, uv.y, T(-1)); break;
    }
    return glm::normalize(normal);
}

} // namespace iblkit::reference
