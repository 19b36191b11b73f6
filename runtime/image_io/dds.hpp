#pragma once

#include "texture.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace iblkit::image_io {

// A DirectDraw Surface with the DX10 extension header, as Microsoft documents DDS_HEADER and
// DDS_HEADER_DXT10 and Direct3D engines load it: DXGI_FORMAT_R16G16B16A16_FLOAT (10),
// R32G32B32A32_FLOAT (2), R16G16_FLOAT (34) or R32G32_FLOAT (16); a cube is flagged in both
// headers (DDSCAPS2_CUBEMAP with all six faces, DDS_RESOURCE_MISC_TEXTURECUBE with arraySize 1);
// the data face after face, each face's mips largest first. Throws ImageError when the texture's
// levels do not match its shape.
std::vector<std::byte> encodeDds(const Texture& texture);

// Reads DX10 files of those four formats and legacy files with the D3DFMT FourCCs 113
// (A16B16G16R16F), 116 (A32B32G32R32F), 112 (G16R16F) and 115 (G32R32F); 2D textures and
// complete cubes. Anything else, and any truncated or inconsistent file, is an ImageError
// naming `name` and the problem.
Texture decodeDds(std::span<const std::byte> bytes, const std::string& name);

} // namespace iblkit::image_io
