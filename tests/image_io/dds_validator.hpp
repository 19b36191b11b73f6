#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace iblkit::testing {

// Checks a DDS file with the DX10 header against Microsoft's DDS_HEADER, DDS_PIXELFORMAT and
// DDS_HEADER_DXT10 documentation, independently of the kit's writer: the magic, the structure
// sizes, the required flags, the FourCC "DX10", the DXGI format (R16G16B16A16_FLOAT,
// R32G32B32A32_FLOAT, R16G16_FLOAT, R32G32_FLOAT), a 2D resource, the cube flags in both headers,
// arraySize, the mip count and its flags, the pitch, and the total size. Returns one line per
// rule broken, each starting with the field it is about; none for a conforming file.
std::vector<std::string> validateDds(std::span<const std::byte> file);

} // namespace iblkit::testing
