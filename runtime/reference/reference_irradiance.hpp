#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace iblkit::reference {

// Cube texels here are RGBA floats ordered face (+X..-Z), row, column, as the runtime uploads them.

// The exact solid angle of texel (column, row) of a size x size face (hlsl/Common/Cube.fxh).
double cubeTexelSolidAngle(uint32_t column, uint32_t row, uint32_t size);

// The unit direction through the centre of texel (column, row) of `face` of a size x size cube.
glm::dvec3 cubeTexelCentre(uint32_t face, uint32_t column, uint32_t row, uint32_t size);

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

// The point sum in double: E(n) / pi per texel of an outSize cube (RGB per texel), each source
// texel's radiance times its solid angle counted at its centre.
std::vector<glm::dvec3> irradianceCube(const std::vector<float>& texels, uint32_t size, uint32_t outSize);

// What IrradianceCubeCS sums: for each texel of a momentSize cube, ∫ L dω over the size x size
// source's texels it covers (each one's radiance times its solid angle), and their mean direction
// weighted by luminance times solid angle, c (of length at most 1; 0 where they are black). Y · max(0,
// n · c), Y the luminance of ∫ L dω, is the texel's luminance's cosine integral wherever its light
// sits inside it, as long as n's horizon does not cut it. RGBA floats, 2 per texel (the radiance
// with w = 0, then c with w = 0), in the texels' order. `size` a multiple of momentSize.
std::vector<float> irradianceMoments(std::span<const float> texels, uint32_t size, uint32_t momentSize);

// IrradianceCubeCS in double: E(n) / pi = Σ over moment texels of ∫ L dω max(0, n · c) / pi.
std::vector<glm::dvec3> irradianceFromMoments(const std::vector<float>& moments, uint32_t momentSize, uint32_t outSize);

// E(n) / pi per texel of an outSize cube, exact for a source of constant texels (black ones skipped): each source
// texel is the spherical quadrilateral its face's straight edges cut, and one that n's horizon
// crosses is clipped to it and integrated by Lambert's formula, ∫ n·l dω = ½ Σ_edges
// angle_i n·unit(v_i × v_(i+1)); a texel clear of the horizon by the same formula's vector,
// ∫ l dω, computed once per texel. The point sum of irradianceCube
// errs where bright texels meet a normal's horizon (a low sun at 128²: 1.5 % of E).
std::vector<glm::dvec3> exactIrradianceCube(const std::vector<float>& texels, uint32_t size, uint32_t outSize);

// One texel of a size x size cube, index (face · size + row) · size + column, and its radiance.
struct CubeTexelRadiance {
    uint32_t index;
    glm::vec3 radiance;
};
// The texels of `texels` (RGBA) that are not black.
std::vector<CubeTexelRadiance> litTexels(const std::vector<float>& texels);
// The same exact sum over the listed texels alone (every other texel black).
std::vector<glm::dvec3> exactIrradianceCube(std::span<const CubeTexelRadiance> texels, uint32_t size, uint32_t outSize);

// E(n) / pi from radiance coefficients (Ramamoorthi and Hanrahan's band factors).
glm::dvec3 shIrradiance(const std::array<glm::dvec3, 9>& radiance, glm::dvec3 normal);

} // namespace iblkit::reference
