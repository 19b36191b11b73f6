#include "texel_checks.hpp"

#include <algorithm>
#include <cmath>

namespace iblkit::bake {
namespace {

constexpr float kLargestHalf = 65504.f;

bool isFiniteTexel(const float* texel, uint32_t channels) {
    for (uint32_t c = 0; c < std::min(channels, 3u); ++c)
        if (!std::isfinite(texel[c])) return false;
    return true;
}

} // namespace

NonFiniteTexels findNonFiniteTexels(std::span<const float> values, uint32_t channels) {
    NonFiniteTexels found;
    for (size_t texel = 0; texel * channels < values.size(); ++texel) {
        const float* at = &values[texel * channels];
        if (isFiniteTexel(at, channels)) continue;
        if (found.count++ == 0) {
            found.firstTexel = texel;
            found.firstValue = *std::find_if(at, at + std::min(channels, 3u), [](float v) { return !std::isfinite(v); });
        }
    }
    return found;
}

size_t replaceNonFiniteTexels(std::span<float> values, uint32_t channels) {
    size_t replaced = 0;
    for (size_t texel = 0; texel * channels < values.size(); ++texel) {
        float* at = &values[texel * channels];
        if (isFiniteTexel(at, channels)) continue;
        std::fill(at, at + std::min(channels, 3u), 0.f);
        ++replaced;
    }
    return replaced;
}

HalfOverflow findHalfOverflow(std::span<const float> values) {
    HalfOverflow found;
    for (size_t i = 0; i < values.size(); ++i) {
        if (std::abs(values[i]) <= kLargestHalf) continue;
        if (found.count++ == 0) found.firstValue = i;
        found.largest = std::max(found.largest, std::abs(values[i]));
    }
    return found;
}

void clampToHalfRange(std::span<float> values) {
    for (float& value : values) value = std::clamp(value, -kLargestHalf, kLargestHalf);
}

} // namespace iblkit::bake
