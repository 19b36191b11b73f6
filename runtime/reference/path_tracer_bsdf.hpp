#pragma once

// hlsl/document/Common/Bsdf.fxh in C++ with GLM, function by function, in the order of operations
// of the HLSL: T = float follows the shader, T = double is the ground truth.

#include "pbr.hpp"

namespace iblkit::reference {

template <typename T>
struct SurfacePoint {
    vec3<T> Position{0};
    vec3<T> Normal{0, 0, 1}; // unit, outward
    vec3<T> Albedo{1};
    T Roughness = T(0.5);
    T Metalness = T(0);
    T Transmittance = T(0);
    T Eta = T(1.5); // the material's index of refraction; the outside's is 1
};

template <typename T>
T D(vec3<T> N, vec3<T> H, T Roughness) {
    const T Roughness4 = Roughness * Roughness * Roughness * Roughness;
    const T NdotH = glm::dot(N, H);
    const T Denominator = NdotH * NdotH * (Roughness4 - T(1)) + T(1);
    return Roughness4 / (PI<T> * Denominator * Denominator);
}

template <typename T>
T G(vec3<T> N, vec3<T> V, vec3<T> L, T Roughness) {
    const T k = (Roughness + T(1)) * (Roughness + T(1)) / T(8);
    const T NdotL = std::abs(glm::dot(N, L));
    const T NdotV = std::abs(glm::dot(N, V));
    return NdotL / (NdotL * (T(1) - k) + k) * (NdotV / (NdotV * (T(1) - k) + k));
}

template <typename T>
vec3<T> F(vec3<T> L, vec3<T> H, vec3<T> F0) {
    return F0 + (T(1) - F0) * std::pow(T(1) - saturate(glm::dot(L, H)), T(5));
}

template <typename T>
vec3<T> BaseReflectance(const SurfacePoint<T>& X) {
    const T Dielectric = (T(1) - X.Eta) / (T(1) + X.Eta);
    return glm::mix(vec3<T>(Dielectric * Dielectric), X.Albedo, X.Metalness);
}

template <typename T>
vec3<T> BRDF(const SurfacePoint<T>& X, vec3<T> L, vec3<T> V) {
    const vec3<T> N = X.Normal;
    const vec3<T> H = glm::normalize(L + V);
    const vec3<T> Fresnel = F(L, H, BaseReflectance(X));
    const vec3<T> kd = (T(1) - Fresnel) * (T(1) - X.Metalness);
    const vec3<T> Diffuse = X.Albedo / PI<T>;
    const vec3<T> Specular = Fresnel * G(N, V, L, X.Roughness) * D(N, H, X.Roughness) /
                             (T(4) * std::abs(glm::dot(N, V)) * std::abs(glm::dot(N, L)));
    return kd * Diffuse + Specular;
}

template <typename T>
vec3<T> BTDF(const SurfacePoint<T>& X, vec3<T> L, vec3<T> V) {
    const vec3<T> N = X.Normal;
    const bool LightOutside = glm::dot(L, N) > T(0);
    const T EtaI = LightOutside ? T(1) : X.Eta;
    const T EtaO = LightOutside ? X.Eta : T(1);
    const vec3<T> H = -glm::normalize(EtaI * L + EtaO * V);
    const vec3<T> Rarer = EtaI <= EtaO ? L : V;
    const vec3<T> Fresnel = F(Rarer, H, BaseReflectance(X));
    const T LdotH = glm::dot(L, H);
    const T VdotH = glm::dot(V, H);
    const T Sum = EtaI * LdotH + EtaO * VdotH;
    return std::abs(LdotH) * std::abs(VdotH) * EtaO * EtaO * (T(1) - Fresnel) / (Sum * Sum) * G(N, V, L, X.Roughness) /
           (std::abs(glm::dot(N, V)) * std::abs(glm::dot(N, L))) * D(N, H, X.Roughness);
}

template <typename T>
vec3<T> BSDF(const SurfacePoint<T>& X, vec3<T> L, vec3<T> V) {
    const T Transmittance = X.Transmittance;
    const vec3<T> N = X.Normal;
    if (glm::dot(L, N) * glm::dot(V, N) > T(0)) return (T(1) - Transmittance) * BRDF(X, L, V);
    return Transmittance * BTDF(X, L, V);
}

} // namespace iblkit::reference
