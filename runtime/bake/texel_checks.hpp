#pragma once

#include <cstdint>
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

struct HalfOverflow {
    size_t count = 0;     // values beyond the largest half, 65504
    float largest = 0;
    size_t firstValue = 0;
};

HalfOverflow findHalfOverflow(std::span<const float> values);
// Clamps those values to +-65504.
void clampToHalfRange(std::span<float> values);

} // namespace iblkit::bake
