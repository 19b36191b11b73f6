#pragma once

// hlsl/document/Common/Random.fxh and Sampling.fxh in C++, function by function, in the order of
// operations of the HLSL: T = float follows the shader, T = double is the ground truth. The
// generator is integer arithmetic and gives the shader's numbers exactly.

#include "pbr.hpp"

#include <cstdint>

namespace iblkit::reference {

struct RandomState {
    uint32_t State = 0;
};

inline uint32_t PcgPermute(uint32_t state) {
    const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

inline RandomState SeedRandom(uint32_t seed, uint32_t stream) { return {PcgPermute(PcgPermute(seed) + stream)}; }

template <typename T>
T Random(RandomState& rng) {
    rng.State = rng.State * 747796405u + 2891336453u;
    return T(PcgPermute(rng.State) >> 8) * (T(1) / T(16777216));
}

template <typename T>
vec3<T> SampleCosineHemisphere(RandomState& rng) {
    const T Random_1 = Random<T>(rng);
    const T Random_2 = Random<T>(rng);
    const T R = std::sqrt(Random_1);
    const T Phi = T(2) * PI<T> * Random_2;
    return vec3<T>(R * std::cos(Phi), R * std::sin(Phi), std::sqrt(T(1) - Random_1));
}

template <typename T>
vec3<T> SampleGGX(T Roughness, RandomState& rng) {
    const T Random_1 = Random<T>(rng);
    const T Random_2 = Random<T>(rng);
    const T Alpha = Roughness * Roughness;
    const T Phi = T(2) * PI<T> * Random_1;
    const T CosTheta = std::sqrt((T(1) - Random_2) / (T(1) + (Alpha * Alpha - T(1)) * Random_2));
    const T SinTheta = std::sqrt(T(1) - CosTheta * CosTheta);
    return glm::normalize(vec3<T>(SinTheta * std::cos(Phi), SinTheta * std::sin(Phi), CosTheta));
}

template <typename T>
T CosineHemispherePdf(T CosTheta) {
    return CosTheta / PI<T>;
}

template <typename T>
T GgxHalfVectorPdf(T CosTheta, T Roughness) {
    const T Alpha2 = Roughness * Roughness * Roughness * Roughness;
    const T Denominator = CosTheta * CosTheta * (Alpha2 - T(1)) + T(1);
    return Alpha2 / (PI<T> * Denominator * Denominator) * CosTheta;
}

} // namespace iblkit::reference
