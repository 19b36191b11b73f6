#pragma once

#include "cube_environment.hpp"

#include <cstdint>
#include <vector>

namespace iblkit::reference {

// PrecomputedBrdfCS over a size x size image: (scale, bias) per texel, row by row; column x is
// NoV = (x + 0.5) / size, row y is roughness = (y + 0.5) / size, as the shader computes them.
template <typename T>
std::vector<T> referenceBrdfLut(uint32_t size, uint32_t sampleCount);

// PrefilterSpecularCS for one roughness over size x size faces: RGBA (alpha 0) per texel,
// ordered face, row, column.
template <typename T>
std::vector<T> referencePrefilter(const CubeEnvironment& environment, T roughness, uint32_t size, uint32_t sampleCount);

} // namespace iblkit::reference
