// BsdfProbeCS's C++ twin: the same surfaces, lights, directions and draws, in the same order.
#include "probe_bake.hpp"

#include "path_tracer_lights.hpp"

namespace iblkit::consistency {
namespace {

using namespace reference;

template <typename T>
vec3<T> probeDirection(T cosTheta, T phi) {
    const T sinTheta = std::sqrt(T(1) - cosTheta * cosTheta);
    return vec3<T>(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
}

template <typename T>
SurfacePoint<T> probeSurface(uint32_t i, T roughness) {
    SurfacePoint<T> X;
    X.Position = vec3<T>(0);
    X.Normal = vec3<T>(0, 0, 1);
    X.Albedo = vec3<T>(T(0.9f), T(0.6f), T(0.3f));
    X.Roughness = roughness;
    X.Metalness = T(0.5f) * T(i % 3u);
    X.Transmittance = T(0.5f);
    X.Eta = T(1.5f);
    return X;
}

template <typename T>
void appendProbe(std::vector<T>& results, uint32_t i, glm::vec4 value) {
    const auto argument = glm::vec<4, T>(value);
    const vec3<T> L = probeDirection(argument.x, T(0)), V = probeDirection(argument.y, argument.w);
    const vec3<T> Below(V.x, V.y, -V.z);
    const auto X = probeSurface<T>(i, argument.z);
    const vec3<T> N = X.Normal;
    RandomState rng = SeedRandom(17u, i);
    const PointLight<T> point{vec3<T>(T(0.3f), T(-0.2f), T(2)), vec3<T>(4, 3, 2)};
    const AreaLight<T> area{vec3<T>(T(-0.5f), T(-0.5f), T(1.5f)), vec3<T>(0, 1, 0), vec3<T>(1, 0, 0), vec3<T>(1, 2, 3)};
    const DirectionalLight<T> sun{glm::normalize(vec3<T>(T(-0.3f), T(0.2f), T(-1))), vec3<T>(5)};
    const auto add = [&results](vec3<T> xyz, T w) { results.insert(results.end(), {xyz.x, xyz.y, xyz.z, w}); };
    add(BRDF(X, L, V), D(N, glm::normalize(L + V), X.Roughness));
    add(BTDF(X, L, Below), G(N, V, L, X.Roughness));
    add(BSDF(X, L, Below), BSDF(X, L, V).y);
    const vec3<T> cosine = SampleCosineHemisphere<T>(rng);
    add(cosine, CosineHemispherePdf(argument.y));
    const vec3<T> half = SampleGGX<T>(X.Roughness, rng);
    add(half, GgxHalfVectorPdf(argument.x, X.Roughness));
    const vec3<T> pointTerm = PointLightTerm(X, V, point, T(1));
    add(pointTerm, Random<T>(rng));
    const vec3<T> lightPoint = SampleAreaLight(area, rng);
    add(AreaLightTerm(X, V, area, lightPoint, T(1)), DirectionalLightTerm(X, V, sun, T(1)).y);
}

} // namespace

template <typename T>
std::vector<T> bsdfProbeReference(const ProbeArguments& arguments) {
    std::vector<T> results;
    results.reserve(arguments.values.size() * kBsdfProbeResults * 4);
    for (uint32_t i = 0; i < arguments.values.size(); ++i) appendProbe(results, i, arguments.values[i]);
    return results;
}

template std::vector<float> bsdfProbeReference<float>(const ProbeArguments&);
template std::vector<double> bsdfProbeReference<double>(const ProbeArguments&);

} // namespace iblkit::consistency
