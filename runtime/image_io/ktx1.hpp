#pragma once

#include "texture.hpp"

#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace iblkit::image_io {

// A KTX 1.1 file (Khronos, "KTX File Format Specification" version 1), as Filament's cmgen
// writes a prefiltered cube and its Ktx1Reader loads one: GL_HALF_FLOAT or GL_FLOAT texels of
// GL_RGBA16F, GL_RGBA32F, GL_RG16F or GL_RG32F; the levels largest first, each prefixed by its
// imageSize (one face's bytes for a cube), its faces +X..-Z within it. `keyValues` go into the
// key/value data, each pair NUL-terminated and padded to 4 bytes. Throws ImageError when the
// texture's levels do not match its shape.
std::vector<std::byte> encodeKtx1(const Texture& texture, const std::map<std::string, std::string>& keyValues = {});

} // namespace iblkit::image_io
