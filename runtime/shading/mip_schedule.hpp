#pragma once

#include <cstdint>
#include <string_view>

namespace iblkit::shading {

// How a shader turns a lookup's roughness into a mip level of the prefiltered cube, and so which
// roughness each mip is prefiltered at (the inverse). n = mips - 1, the last level:
//   - Linear: lod = r n (the documents, the glTF Sample Viewer);
//   - Quadratic: lod = r (2 - r) n (three.js r187, Filament);
//   - Power: lod = r^p n;
//   - Babylon: lod = 0.8 log2(α size), α = r² (Babylon.js's lodGenerationScale, no offset),
//     clamped to [0, n];
//   - Logarithmic: lod = k log2(α size) + b, clamped to [0, n], with mip 1 at α = c / size and mip
//     n at α = 1: Babylon's spacing in α, but a chain of any length ends at roughness 1 (a chain
//     of fewer than 3 mips, or of faces no larger than c, maps linearly).
// Mip 0 is the source itself, roughness 0, for every mapping.
enum class LodMapping { Linear, Quadratic, Power, Babylon, Logarithmic };

std::string_view nameOf(LodMapping mapping);
// Throws std::invalid_argument for another name.
LodMapping lodMappingNamed(std::string_view name);

struct MipSchedule {
    LodMapping mapping = LodMapping::Linear;
    double parameter = 1; // Power's p; Logarithmic's c
    uint32_t mips = 1; // levels, mip 0 included
    uint32_t size = 1; // mip 0's face size (Babylon's)

    double lodOf(double roughness) const;
    // The roughness mip `mip` is prefiltered at: the roughness whose lod is `mip` (mip 0: 0).
    double roughnessOf(uint32_t mip) const;
};

} // namespace iblkit::shading
