#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace iblkit::image_io {

// The texel formats the kit's KTX2 and DDS files hold: 16- or 32-bit floats, RGBA or RG.
enum class PixelFormat { Rgba16Float, Rgba32Float, Rg16Float, Rg32Float };

uint32_t channelCount(PixelFormat format);
uint32_t bytesPerChannel(PixelFormat format);
uint32_t bytesPerTexel(PixelFormat format);
// The VkFormat name without its VK_FORMAT_ prefix, e.g. "R16G16B16A16_SFLOAT".
std::string_view vulkanFormatName(PixelFormat format);

// A texture in GPU layout, what KTX2 and DDS files hold.
struct Texture {
    PixelFormat format = PixelFormat::Rgba16Float;
    uint32_t width = 0, height = 0;
    uint32_t faces = 1; // 1, or 6 for a cube in the order +X, -X, +Y, -Y, +Z, -Z
    uint32_t mips = 1;
    // levels[mip]: every face of that mip, face after face, each face rows top first, texels
    // tightly packed.
    std::vector<std::vector<std::byte>> levels;

    uint32_t mipWidth(uint32_t mip) const; // max(1, width >> mip)
    uint32_t mipHeight(uint32_t mip) const;
    size_t faceBytes(uint32_t mip) const;
};

// From values ordered mip, face, row, column, channel (channelCount(format) channels). Halves are
// rounded to nearest even; a value beyond the half range becomes an infinity of its sign, so
// callers apply their own policy first. Throws ImageError when the shape is not one a KTX2 or DDS
// file can hold or the number of values does not match it.
Texture makeTexture(PixelFormat format, uint32_t width, uint32_t height, uint32_t faces, uint32_t mips,
                    std::span<const float> values);
// The inverse of makeTexture, in the same order.
std::vector<float> textureValues(const Texture& texture);

} // namespace iblkit::image_io
