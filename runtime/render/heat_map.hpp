#pragma once

#include <cstdint>
#include <vector>

namespace iblkit::render {

// Relative errors at or beyond this show at the colour scale's ends.
inline constexpr double kHeatMapRange = 0.5;

struct Rgba8Image {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba;
};

// The signed relative errors of a width x height image (0 outside the spheres, drawn black where
// `covered` is false) on a diverging scale, blue where the split sum is darker than the reference,
// red where it is brighter, white where they agree; under it, the scale's legend from
// -kHeatMapRange to +kHeatMapRange with its ticks labelled in percent.
Rgba8Image heatMap(const std::vector<double>& errors, const std::vector<bool>& covered, uint32_t width, uint32_t height);

} // namespace iblkit::render
