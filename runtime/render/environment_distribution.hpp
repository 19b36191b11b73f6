#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace iblkit::render {

// The share of RenderReferenceCS's environment draws spread by solid angle alone, so that every
// direction has a density (a texel the distribution's mip shows dark may still hold light) and
// an environment of zeros still has a distribution.
inline constexpr double kUniformShare = 0.1;

// The cumulative distribution RenderReferenceCS draws directions from: texel i of a cube of
// faceSize² faces (RGBA floats, face +X..-Z, row, column) with probability
// (1 - kUniformShare) luminance_i solid_angle_i / sum + kUniformShare solid_angle_i / 4 pi.
// Each entry is rounded to a multiple of 2^-24, the grid Random() draws on, with every texel
// at least one step wide: a draw then lands in a texel exactly as often as the difference of its
// entries, which is the density the shader divides by. The last entry is 1.
std::vector<float> environmentCdf(std::span<const float> faces, uint32_t faceSize);

} // namespace iblkit::render
