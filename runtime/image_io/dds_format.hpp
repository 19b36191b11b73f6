#pragma once

// Microsoft's DDS layout (DDS_HEADER, DDS_PIXELFORMAT, DDS_HEADER_DXT10) as the kit's DDS writer
// and reader share it. Offsets are from the start of the file, after the 4-byte magic.
#include "texture.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace iblkit::image_io::dds {

inline constexpr uint32_t kMagic = 0x20534444; // "DDS "
inline constexpr uint32_t kHeaderSize = 124, kPixelFormatSize = 32;

// DDS_HEADER fields.
inline constexpr size_t kSize = 4, kFlags = 8, kHeight = 12, kWidth = 16, kPitchOrLinearSize = 20, kDepth = 24,
                        kMipMapCount = 28, kPixelFormat = 76, kCaps = 108, kCaps2 = 112, kHeaderEnd = 128;
// DDS_PIXELFORMAT fields.
inline constexpr size_t kPixelFormatFlags = 80, kFourCc = 84;
// DDS_HEADER_DXT10 fields.
inline constexpr size_t kDxgiFormat = 128, kResourceDimension = 132, kMiscFlag = 136, kArraySize = 140,
                        kMiscFlags2 = 144, kDx10HeaderEnd = 148;

inline constexpr uint32_t kFlagCaps = 0x1, kFlagHeight = 0x2, kFlagWidth = 0x4, kFlagPitch = 0x8,
                          kFlagPixelFormat = 0x1000, kFlagMipMapCount = 0x20000, kFlagDepth = 0x800000;
inline constexpr uint32_t kPixelFormatFourCc = 0x4;
inline constexpr uint32_t kFourCcDx10 = 0x30315844; // "DX10"
inline constexpr uint32_t kCapsComplex = 0x8, kCapsTexture = 0x1000, kCapsMipMap = 0x400000;
inline constexpr uint32_t kCaps2Cubemap = 0x200, kCaps2AllFaces = 0xFC00, kCaps2Volume = 0x200000;
inline constexpr uint32_t kDimensionTexture1D = 2, kDimensionTexture2D = 3, kDimensionTexture3D = 4;
inline constexpr uint32_t kMiscTextureCube = 0x4;

uint32_t dxgiFormatOf(PixelFormat format);
std::optional<PixelFormat> formatOfDxgiFormat(uint32_t dxgiFormat);
// The D3DFMT FourCC codes of legacy float files.
std::optional<PixelFormat> formatOfLegacyFourCc(uint32_t fourCc);

} // namespace iblkit::image_io::dds
