#pragma once

// The parts of the KTX 2.0 file layout (Khronos KTX File Format Specification 2.0) that the
// kit's writer and reader share.
#include "texture.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace iblkit::image_io::ktx2 {

inline constexpr std::array<uint8_t, 12> kIdentifier = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32,
                                                        0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};

// Byte offsets of the header fields, each a UInt32 after the identifier.
inline constexpr size_t kVkFormat = 12, kTypeSize = 16, kPixelWidth = 20, kPixelHeight = 24, kPixelDepth = 28,
                        kLayerCount = 32, kFaceCount = 36, kLevelCount = 40, kSupercompressionScheme = 44;
// The index: UInt32 dfd/kvd offsets and lengths, UInt64 sgd offset and length.
inline constexpr size_t kDfdByteOffset = 48, kDfdByteLength = 52, kKvdByteOffset = 56, kKvdByteLength = 60,
                        kSgdByteOffset = 64, kSgdByteLength = 72;
// The level index follows: per level UInt64 byteOffset, byteLength, uncompressedByteLength.
inline constexpr size_t kLevelIndex = 80, kLevelIndexEntry = 24;

uint32_t vkFormatOf(PixelFormat format);
std::optional<PixelFormat> formatOfVkFormat(uint32_t vkFormat);

// Levels start on a multiple of lcm(texel block size, 4) when there is no supercompression.
size_t levelAlignment(PixelFormat format);

} // namespace iblkit::image_io::ktx2
