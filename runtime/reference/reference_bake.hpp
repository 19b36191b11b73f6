#pragma once

#include "cube_environment.hpp"

#include <array>
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

// The kit's cube kernels (hlsl/*.hlsl with Common/Cube.fxh), each following its shader's
// arithmetic step by step. Cube texels are RGBA floats ordered face, row, column.

// EquirectToCubeCS: an RGBA panorama (width x height, row 0 at the zenith) onto size x size
// faces, each texel the mean of supersample² bilinear reads (longitude wraps, latitude clamps);
// RGBA with alpha 1. T = float follows the shader, T = double is the truth for those texels.
template <typename T>
std::vector<T> referenceEquirectToCube(const std::vector<float>& panorama, uint32_t width, uint32_t height, uint32_t size,
                                       uint32_t supersample);

// DownsampleCubeCS in float: the next mip of a size x size cube, ((a + b) + c + d) * 0.25f per
// channel in the shader's order (reference::downsampleCube is the same mean in double).
std::vector<float> downsampleCubeInFloat(const std::vector<float>& texels, uint32_t size);

// ShProjectCS in float: radiance · Y_lm · solid angle per texel in float, each 8x8 block
// reduced in the shader's tree order, the blocks added in double as the host adds them.
struct ShSums {
    std::array<glm::dvec3, 9> radiance;
    double solidAngle;
};
ShSums projectOnShInFloat(const std::vector<float>& texels, uint32_t size);

// IrradianceCubeCS in float: E(n) / pi per texel of an outSize cube, summed over the moments
// (reference::irradianceMoments) in the shader's order; RGBA with alpha 1.
std::vector<float> irradianceCubeInFloat(const std::vector<float>& moments, uint32_t momentSize, uint32_t outSize);

} // namespace iblkit::reference
