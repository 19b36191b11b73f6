#pragma once

#include "texture.hpp"

#include <cstdint>
#include <string>

namespace iblkit::image_io {

// Larger textures are refused before anything is allocated for them.
inline constexpr uint32_t kMaxTextureSide = 65536;

// floor(log2(max(width, height))) + 1: the mips down to 1x1.
uint32_t fullMipCount(uint32_t width, uint32_t height);

// What is wrong with a texture of this shape, as the end of a sentence about it ("is a cube with
// faces that are not square (8x4)"), or "" when the kit's KTX2 and DDS files can hold it.
std::string shapeProblem(uint32_t width, uint32_t height, uint32_t faces, uint32_t mips);

// Throws ImageError "<who>: <problem>" when the texture's shape is wrong or its levels do not
// hold exactly the bytes the shape needs.
void requireConsistent(const Texture& texture, const std::string& who);

} // namespace iblkit::image_io
