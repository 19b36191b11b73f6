#include "texel_checks.hpp"

#include <algorithm>
#include <cmath>

namespace iblkit::bake {
namespace {

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

NegativeTexels findNegativeTexels(std::span<const float> values, uint32_t channels) {
    NegativeTexels found;
    for (size_t texel = 0; texel * channels < values.size(); ++texel) {
        const float* at = &values[texel * channels];
        const float least = *std::min_element(at, at + std::min(channels, 3u));
        if (!(least < 0.f)) continue;
        ++found.count;
        found.mostNegative = std::min(found.mostNegative, least);
    }
    return found;
}

void clampNegativeToZero(std::span<float> values, uint32_t channels) {
    for (size_t texel = 0; texel * channels < values.size(); ++texel)
        for (uint32_t c = 0; c < std::min(channels, 3u); ++c) {
            float& value = values[texel * channels + c];
            value = std::max(value, 0.f);
        }
}

std::optional<OversizedTexel> findOversizedTexel(std::span<const float> values, uint32_t channels) {
    for (size_t texel = 0; texel * channels < values.size(); ++texel)
        for (uint32_t c = 0; c < std::min(channels, 3u); ++c) {
            const float value = values[texel * channels + c];
            if (std::abs(value) > kLargestRadiance) return OversizedTexel{texel, value};
        }
    return std::nullopt;
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
