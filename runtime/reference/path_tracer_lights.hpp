#pragma once

// hlsl/document/Common/Lights.fxh in C++ with GLM, function by function, in the order of
// operations of the HLSL: T = float follows the shader, T = double is the ground truth.

#include "path_tracer_bsdf.hpp"
#include "path_tracer_sampling.hpp"

namespace iblkit::reference {

template <typename T>
struct DirectionalLight {
    vec3<T> Direction; // the direction the light travels, unit
    vec3<T> Radiance;
};

template <typename T>
struct PointLight {
    vec3<T> Position;
    vec3<T> Radiance; // intensity
};

template <typename T>
struct AreaLight {
    vec3<T> Corner, EdgeU, EdgeV; // emitting on the side of cross(EdgeU, EdgeV)
    vec3<T> Radiance;
};

template <typename T>
vec3<T> DirectionalLightTerm(const SurfacePoint<T>& X, vec3<T> V, const DirectionalLight<T>& Light, T Visibility) {
    const vec3<T> L = -Light.Direction;
    return BSDF(X, L, V) * Light.Radiance * Visibility * std::abs(glm::dot(X.Normal, L));
}

template <typename T>
vec3<T> PointLightTerm(const SurfacePoint<T>& X, vec3<T> V, const PointLight<T>& Light, T Visibility) {
    const vec3<T> ToLight = Light.Position - X.Position;
    const T Distance2 = glm::dot(ToLight, ToLight);
    const vec3<T> L = ToLight * (T(1) / std::sqrt(Distance2));
    return BSDF(X, L, V) * Light.Radiance * Visibility * std::abs(glm::dot(X.Normal, L)) / Distance2;
}

template <typename T>
vec3<T> SampleAreaLight(const AreaLight<T>& Light, RandomState& rng) {
    const T u = Random<T>(rng);
    const T v = Random<T>(rng);
    return Light.Corner + u * Light.EdgeU + v * Light.EdgeV;
}

template <typename T>
vec3<T> AreaLightTerm(const SurfacePoint<T>& X, vec3<T> V, const AreaLight<T>& Light, vec3<T> LightPoint, T Visibility) {
    const vec3<T> Across = glm::cross(Light.EdgeU, Light.EdgeV);
    const T Area = glm::length(Across);
    const vec3<T> LightNormal = Across / Area;
    const vec3<T> ToLight = LightPoint - X.Position;
    const T Distance2 = glm::dot(ToLight, ToLight);
    const vec3<T> L = ToLight * (T(1) / std::sqrt(Distance2));
    const T Emitting = glm::dot(LightNormal, -L) > T(0) ? T(1) : T(0);
    const T Geometry = std::abs(glm::dot(X.Normal, L)) * std::abs(glm::dot(LightNormal, L)) / Distance2;
    return BSDF(X, L, V) * Light.Radiance * Emitting * Visibility * Geometry * Area;
}

} // namespace iblkit::reference
