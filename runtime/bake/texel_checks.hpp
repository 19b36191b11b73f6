#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace iblkit::bake {

struct NonFiniteTexels {
    size_t count = 0;     // texels with a NaN or infinite colour channel
    size_t firstTexel = 0; // index of the first, in row order
    float firstValue = 0;
};

// Looks at the first three channels of each texel (alpha carries no light).
NonFiniteTexels findNonFiniteTexels(std::span<const float> values, uint32_t channels);
// Sets every colour channel of such texels to 0; returns how many texels changed.
size_t replaceNonFiniteTexels(std::span<float> values, uint32_t channels);

struct NegativeTexels {
    size_t count = 0;        // texels with a negative colour channel
    float mostNegative = 0;  // the most negative such channel
};

NegativeTexels findNegativeTexels(std::span<const float> values, uint32_t channels);
// Sets every negative colour channel to 0.
void clampNegativeToZero(std::span<float> values, uint32_t channels);

// The largest radiance the bake takes. The kernels multiply radiance by lobe weights up to about
// 1e4 (GGX's D at the smallest roughness of a long chain) and sum up to 2^20 samples in 32-bit
// floats; 1e20 keeps 1e18 of headroom below FLT_MAX (3.4e38) for them, and eleven orders of
// magnitude above the sun's luminance (1.6e9 cd/m²), the brightest thing an HDRI photographs.
// Measured: a one-texel 1e35 still bakes with every method at the default settings; 1e37 gives Inf.
inline constexpr float kLargestRadiance = 1e20f;

struct OversizedTexel {
    size_t texel = 0; // the first texel with a colour channel beyond ±kLargestRadiance, in row order
    float value = 0;
};

std::optional<OversizedTexel> findOversizedTexel(std::span<const float> values, uint32_t channels);

inline constexpr float kLargestHalf = 65504.f;

struct HalfOverflow {
    size_t count = 0;     // values beyond the largest half, 65504
    float largest = 0;
    size_t firstValue = 0;
};

HalfOverflow findHalfOverflow(std::span<const float> values);
// Clamps those values to +-65504.
void clampToHalfRange(std::span<float> values);

} // namespace iblkit::bake
