#include "texture.hpp"

#include "fresh_memory.hpp"
#include "half_float.hpp"
#include "image_error.hpp"
#include "texture_shape.hpp"

#include <algorithm>
#include <cstring>

namespace iblkit::image_io {
namespace {

void storeHalf(std::byte* to, float value) {
    const uint16_t half = numeric::toHalfBits(value);
    std::memcpy(to, &half, sizeof half);
}

float loadHalf(const std::byte* from) {
    uint16_t half;
    std::memcpy(&half, from, sizeof half);
    return numeric::fromHalfBits(half);
}

size_t valueCount(const Texture& texture) {
    size_t count = 0;
    for (uint32_t mip = 0; mip < texture.mips; ++mip) count += texture.faceBytes(mip) * texture.faces;
    return count / bytesPerChannel(texture.format);
}

} // namespace

uint32_t channelCount(PixelFormat format) {
    return format == PixelFormat::Rgba16Float || format == PixelFormat::Rgba32Float ? 4 : 2;
}

uint32_t bytesPerChannel(PixelFormat format) {
    return format == PixelFormat::Rgba16Float || format == PixelFormat::Rg16Float ? 2 : 4;
}

uint32_t bytesPerTexel(PixelFormat format) { return channelCount(format) * bytesPerChannel(format); }

std::string_view vulkanFormatName(PixelFormat format) {
    switch (format) {
    case PixelFormat::Rgba16Float: return "R16G16B16A16_SFLOAT";
    case PixelFormat::Rgba32Float: return "R32G32B32A32_SFLOAT";
    case PixelFormat::Rg16Float: return "R16G16_SFLOAT";
    case PixelFormat::Rg32Float: return "R32G32_SFLOAT";
    }
    return "?";
}

uint32_t Texture::mipWidth(uint32_t mip) const { return std::max(1u, mip < 32 ? width >> mip : 0); }
uint32_t Texture::mipHeight(uint32_t mip) const { return std::max(1u, mip < 32 ? height >> mip : 0); }
size_t Texture::faceBytes(uint32_t mip) const { return size_t(mipWidth(mip)) * mipHeight(mip) * bytesPerTexel(format); }

Texture makeTexture(PixelFormat format, uint32_t width, uint32_t height, uint32_t faces, uint32_t mips,
                    std::span<const float> values) {
    const auto problem = shapeProblem(width, height, faces, mips);
    if (!problem.empty()) throw ImageError("makeTexture: the texture " + problem);
    Texture texture{format, width, height, faces, mips, {}};
    if (values.size() != valueCount(texture))
        throw ImageError("makeTexture: " + std::to_string(values.size()) + " values given; the texture holds " +
                         std::to_string(valueCount(texture)));
    const bool half = bytesPerChannel(format) == 2;
    const float* next = values.data();
    for (uint32_t mip = 0; mip < mips; ++mip) {
        std::vector<std::byte> level;
        resizePopulated(level, texture.faceBytes(mip) * faces);
        for (size_t at = 0; at < level.size(); at += bytesPerChannel(format), ++next) {
            if (half) storeHalf(level.data() + at, *next);
            else std::memcpy(level.data() + at, next, sizeof(float));
        }
        texture.levels.push_back(std::move(level));
    }
    return texture;
}

std::vector<float> textureValues(const Texture& texture) {
    std::vector<float> values;
    const bool half = bytesPerChannel(texture.format) == 2;
    for (const auto& level : texture.levels)
        for (size_t at = 0; at + bytesPerChannel(texture.format) <= level.size(); at += bytesPerChannel(texture.format)) {
            float value;
            if (half) value = loadHalf(level.data() + at);
            else std::memcpy(&value, level.data() + at, sizeof value);
            values.push_back(value);
        }
    return values;
}

} // namespace iblkit::image_io
