#include "byte_io.hpp"
#include "ktx1.hpp"
#include "texture_shape.hpp"

#include <array>
#include <cstdint>

namespace iblkit::image_io {
namespace {

constexpr std::array<uint8_t, 12> kKtx1Identifier = {0xAB, 'K', 'T', 'X', ' ', '1', '1', 0xBB, '\r', '\n', 0x1A, '\n'};
constexpr uint32_t kEndianness = 0x04030201;

// OpenGL's enumerants for a format: glType, glFormat and glInternalFormat.
struct GlFormat {
    uint32_t type, format, internalFormat;
};

GlFormat glFormatOf(PixelFormat format) {
    constexpr uint32_t kHalfFloat = 0x140B, kFloat = 0x1406, kRgba = 0x1908, kRg = 0x8227;
    switch (format) {
    case PixelFormat::Rgba16Float: return {kHalfFloat, kRgba, 0x881A};
    case PixelFormat::Rgba32Float: return {kFloat, kRgba, 0x8814};
    case PixelFormat::Rg16Float: return {kHalfFloat, kRg, 0x822F};
    case PixelFormat::Rg32Float: return {kFloat, kRg, 0x8230};
    }
    return {kHalfFloat, kRgba, 0x881A};
}

void putKeyValues(ByteWriter& out, const std::map<std::string, std::string>& keyValues) {
    for (const auto& [key, value] : keyValues) {
        const uint32_t size = uint32_t(key.size() + 1 + value.size() + 1);
        out.put(size);
        out.putBytes(std::as_bytes(std::span(key)));
        out.put(uint8_t(0));
        out.putBytes(std::as_bytes(std::span(value)));
        out.put(uint8_t(0));
        out.padTo(4);
    }
}

} // namespace

std::vector<std::byte> encodeKtx1(const Texture& texture, const std::map<std::string, std::string>& keyValues) {
    requireConsistent(texture, "encodeKtx1");
    const GlFormat gl = glFormatOf(texture.format);
    ByteWriter out;
    for (uint8_t byte : kKtx1Identifier) out.put(byte);
    out.put(kEndianness);
    out.put(gl.type);
    out.put(bytesPerChannel(texture.format)); // glTypeSize
    out.put(gl.format);
    out.put(gl.internalFormat);
    out.put(gl.format); // glBaseInternalFormat
    out.put(texture.width);
    out.put(texture.height);
    out.put<uint32_t>(0); // pixelDepth: a 2D texture or a cube
    out.put<uint32_t>(0); // numberOfArrayElements: not an array
    out.put(texture.faces);
    out.put(texture.mips);
    const size_t keyValueSizeAt = out.size();
    out.put<uint32_t>(0);
    putKeyValues(out, keyValues);
    out.putAt(keyValueSizeAt, uint32_t(out.size() - keyValueSizeAt - sizeof(uint32_t)));
    for (uint32_t mip = 0; mip < texture.mips; ++mip) {
        // imageSize: a non-array cube's is one face's bytes; every row of a float texel is a
        // multiple of 4 bytes, so no row, face or level needs padding.
        out.put(uint32_t(texture.faceBytes(mip) * (texture.faces == 6 ? 1 : texture.faces)));
        out.putBytes(texture.levels[mip]);
    }
    return out.take();
}

} // namespace iblkit::image_io
