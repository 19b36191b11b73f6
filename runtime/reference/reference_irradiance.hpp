#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace iblkit::reference {

// Cube texels here are RGBA floats ordered face (+X..-Z), row, column, as the runtime uploads them.

// The exact solid angle of texel (column, row) of a size x size face (hlsl/Common/Cube.fxh).
double cubeTexelSolidAngle(uint32_t column, uint32_t row, uint32_t size);

// Real spherical harmonics of bands 0-2 in hlsl/Common/SphericalHarmonics.fxh's order.
// In T's arithmetic with T's constants, so T = float follows the shader.
template <typename T>
std::array<T, 9> shBasis(glm::vec<3, T> d) {
    return {T(0.282094791773878),
            T(0.488602511902920) * d.y,
            T(0.488602511902920) * d.z,
            T(0.488602511902920) * d.x,
            T(1.092548430592079) * d.x * d.y,
            T(1.092548430592079) * d.y * d.z,
            T(0.315391565252520) * (T(3) * d.z * d.z - T(1)),
            T(1.092548430592079) * d.x * d.z,
            T(0.546274215296040) * (d.x * d.x - d.y * d.y)};
}

// DownsampleCubeCS: each texel of the next mip is the mean of a 2x2 block.
std::vector<float> downsampleCube(const std::vector<float>& texels, uint32_t size);

// ShProjectCS in double: sum over texels of radiance * Y_lm(texel centre) * solid angle.
std::array<glm::dvec3, 9> projectOnSh(const std::vector<float>& texels, uint32_t size);

// IrradianceCubeCS in double: E(n) / pi per texel of an outSize cube (RGB per texel).
std::vector<glm::dvec3> irradianceCube(const std::vector<float>& texels, uint32_t size, uint32_t outSize);

// E(n) / pi from radiance coefficients (Ramamoorthi and Hanrahan's band factors).
glm::dvec3 shIrradiance(const std::array<glm::dvec3, 9>& radiance, glm::dvec3 normal);

} // namespace iblkit::reference
