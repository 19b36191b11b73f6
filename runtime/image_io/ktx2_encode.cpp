#include "byte_io.hpp"
#include "data_format_descriptor.hpp"
#include "key_value_data.hpp"
#include "ktx2.hpp"
#include "ktx2_format.hpp"
#include "texture_shape.hpp"

#include <array>

namespace iblkit::image_io {
namespace {

using namespace ktx2;

void putHeader(ByteWriter& out, const Texture& texture) {
    for (uint8_t byte : kIdentifier) out.put(byte);
    out.put(vkFormatOf(texture.format));
    out.put(bytesPerChannel(texture.format)); // typeSize
    out.put(texture.width);
    out.put(texture.height);
    out.put<uint32_t>(0); // pixelDepth: not 3D
    out.put<uint32_t>(0); // layerCount: not an array
    out.put(texture.faces);
    out.put(texture.mips);
    out.put<uint32_t>(0); // supercompressionScheme: none
}

void putIndex(ByteWriter& out, size_t dfdOffset, size_t dfdLength, size_t kvdLength) {
    out.put(uint32_t(dfdOffset));
    out.put(uint32_t(dfdLength));
    out.put(uint32_t(dfdOffset + dfdLength)); // the key/value data follow the DFD
    out.put(uint32_t(kvdLength));
    out.put<uint64_t>(0); // no supercompression global data
    out.put<uint64_t>(0);
}

// Levels are at most 16-byte aligned (lcm(texel size, 4)).
constexpr std::array<std::byte, 16> kPadding{};

} // namespace

Ktx2Pieces encodeKtx2Pieces(const Texture& texture, const std::string& writer,
                            const std::map<std::string, std::string>& keyValues) {
    requireConsistent(texture, "encodeKtx2");
    const auto dfd = dataFormatDescriptor(texture.format);
    auto entries = keyValues;
    entries["KTXwriter"] = writer;
    const auto kvd = keyValueData(entries);
    ByteWriter out;
    putHeader(out, texture);
    putIndex(out, kLevelIndex + kLevelIndexEntry * texture.mips, dfd.size(), kvd.size());
    out.putZeros(kLevelIndexEntry * texture.mips); // filled in below
    out.putBytes(dfd);
    out.putBytes(kvd);
    Ktx2Pieces file;
    std::vector<std::span<const std::byte>> levels;
    uint64_t offset = out.size();
    const size_t alignment = levelAlignment(texture.format);
    for (uint32_t mip = texture.mips; mip-- > 0;) { // the smallest level first
        const size_t padding = (alignment - offset % alignment) % alignment;
        if (padding > 0) levels.push_back(std::span(kPadding).first(padding));
        offset += padding;
        const uint64_t length = texture.levels[mip].size();
        levels.push_back(texture.levels[mip]);
        const size_t entry = kLevelIndex + kLevelIndexEntry * mip;
        out.putAt(entry, offset);
        out.putAt(entry + 8, length);
        out.putAt(entry + 16, length); // uncompressedByteLength
        offset += length;
    }
    file.head = out.take();
    file.pieces.push_back(file.head);
    file.pieces.insert(file.pieces.end(), levels.begin(), levels.end());
    return file;
}

std::vector<std::byte> encodeKtx2(const Texture& texture, const std::string& writer,
                                  const std::map<std::string, std::string>& keyValues) {
    const auto file = encodeKtx2Pieces(texture, writer, keyValues);
    std::vector<std::byte> bytes;
    size_t size = 0;
    for (const auto piece : file.pieces) size += piece.size();
    bytes.reserve(size);
    for (const auto piece : file.pieces) bytes.insert(bytes.end(), piece.begin(), piece.end());
    return bytes;
}

} // namespace iblkit::image_io
