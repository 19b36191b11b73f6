#include "byte_io.hpp"
#include "data_format_descriptor.hpp"
#include "key_value_data.hpp"
#include "ktx2.hpp"
#include "ktx2_format.hpp"
#include "texture_shape.hpp"

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

void putLevels(ByteWriter& out, const Texture& texture) {
    for (uint32_t mip = texture.mips; mip-- > 0;) { // the smallest level first
        out.padTo(levelAlignment(texture.format));
        const uint64_t offset = out.size(), length = texture.levels[mip].size();
        out.putBytes(texture.levels[mip]);
        const size_t entry = kLevelIndex + kLevelIndexEntry * mip;
        out.putAt(entry, offset);
        out.putAt(entry + 8, length);
        out.putAt(entry + 16, length); // uncompressedByteLength
    }
}

} // namespace

std::vector<std::byte> encodeKtx2(const Texture& texture, const std::string& writer,
                                  const std::map<std::string, std::string>& keyValues) {
    requireConsistent(texture, "encodeKtx2");
    const auto dfd = dataFormatDescriptor(texture.format);
    auto entries = keyValues;
    entries["KTXwriter"] = writer;
    const auto kvd = keyValueData(entries);
    ByteWriter out;
    size_t levelBytes = 0;
    for (const auto& level : texture.levels) levelBytes += level.size() + 16; // and its alignment
    out.reserve(kLevelIndex + kLevelIndexEntry * texture.mips + dfd.size() + kvd.size() + levelBytes);
    putHeader(out, texture);
    putIndex(out, kLevelIndex + kLevelIndexEntry * texture.mips, dfd.size(), kvd.size());
    out.putZeros(kLevelIndexEntry * texture.mips); // filled in by putLevels
    out.putBytes(dfd);
    out.putBytes(kvd);
    putLevels(out, texture);
    return out.take();
}

} // namespace iblkit::image_io
