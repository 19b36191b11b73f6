#include "ktx1_validator.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>

namespace iblkit::testing {
namespace {

constexpr std::array<unsigned char, 12> kIdentifier = {0xAB, 'K', 'T', 'X', ' ', '1', '1', 0xBB, '\r', '\n', 0x1A, '\n'};
constexpr uint32_t kHalfFloat = 0x140B, kFloat = 0x1406, kRgba = 0x1908, kRg = 0x8227;

uint32_t word(std::span<const std::byte> file, size_t offset) {
    uint32_t value = 0;
    std::memcpy(&value, file.data() + offset, 4);
    return value;
}

// The sized internal format the specification pairs with a type and a format.
uint32_t sizedFormat(uint32_t type, uint32_t format) {
    if (format == kRgba) return type == kHalfFloat ? 0x881A : 0x8814;
    return type == kHalfFloat ? 0x822F : 0x8230;
}

size_t padded(size_t size) { return (size + 3) / 4 * 4; }

void checkKeyValues(std::span<const std::byte> file, size_t start, size_t length, std::vector<std::string>& errors) {
    size_t offset = start;
    while (offset < start + length) {
        if (offset + 4 > start + length) return errors.push_back("bytesOfKeyValueData: a pair's size runs past the data");
        const uint32_t size = word(file, offset);
        const size_t end = offset + 4 + size;
        if (end > start + length) return errors.push_back("keyAndValueByteSize: a pair runs past the key/value data");
        const auto* key = reinterpret_cast<const char*>(file.data() + offset + 4);
        if (std::find(key, key + size, '\0') == key + size) errors.push_back("key: not NUL-terminated");
        offset = offset + 4 + padded(size);
    }
    if (offset != start + length) errors.push_back("valuePadding: the last pair's padding runs past the key/value data");
}

} // namespace

std::vector<std::string> validateKtx1(std::span<const std::byte> file) {
    std::vector<std::string> errors;
    if (file.size() < 64) return {"header: the file is shorter than the 64-byte header"};
    if (std::memcmp(file.data(), kIdentifier.data(), kIdentifier.size()) != 0) errors.push_back("identifier: not «KTX 11»");
    if (word(file, 12) != 0x04030201) errors.push_back("endianness: not 0x04030201 as written");
    const uint32_t type = word(file, 16), typeSize = word(file, 20), format = word(file, 24);
    const uint32_t internalFormat = word(file, 28), baseFormat = word(file, 32);
    const uint32_t width = word(file, 36), height = word(file, 40), depth = word(file, 44);
    const uint32_t arrayElements = word(file, 48), faces = word(file, 52), mips = word(file, 56);
    const uint32_t keyValueBytes = word(file, 60);
    if (type != kHalfFloat && type != kFloat) errors.push_back("glType: neither GL_HALF_FLOAT nor GL_FLOAT");
    if (typeSize != (type == kHalfFloat ? 2u : 4u)) errors.push_back("glTypeSize: not the size of glType");
    if (format != kRgba && format != kRg) errors.push_back("glFormat: neither GL_RGBA nor GL_RG");
    if (baseFormat != format) errors.push_back("glBaseInternalFormat: not glFormat");
    if (internalFormat != sizedFormat(type, format)) errors.push_back("glInternalFormat: not the sized format of glType and glFormat");
    if (width == 0 || height == 0) errors.push_back("pixelWidth: a 2D texture has a width and a height");
    if (depth != 0) errors.push_back("pixelDepth: not 0 (2D or cube)");
    if (arrayElements != 0) errors.push_back("numberOfArrayElements: not 0");
    if (faces != 1 && faces != 6) errors.push_back("numberOfFaces: neither 1 nor 6");
    if (faces == 6 && width != height) errors.push_back("numberOfFaces: a cube's faces are square");
    if (mips == 0 || mips > uint32_t(std::bit_width(std::max(width, height)))) errors.push_back("numberOfMipmapLevels: out of range");
    if (!errors.empty()) return errors;
    if (keyValueBytes % 4 != 0) errors.push_back("bytesOfKeyValueData: not a multiple of 4");
    if (64 + size_t(keyValueBytes) > file.size()) return {"bytesOfKeyValueData: runs past the file"};
    checkKeyValues(file, 64, keyValueBytes, errors);
    const size_t texel = (format == kRgba ? 4 : 2) * typeSize;
    size_t offset = 64 + keyValueBytes;
    for (uint32_t mip = 0; mip < mips; ++mip) {
        const size_t w = std::max(width >> mip, 1u), h = std::max(height >> mip, 1u);
        const size_t rowBytes = padded(w * texel), faceBytes = rowBytes * h;
        if (offset + 4 > file.size()) return errors.push_back("imageSize: the file ends before mip " + std::to_string(mip)), errors;
        const size_t imageSize = word(file, offset);
        if (imageSize != faceBytes) // one face's bytes: the whole image of a 2D texture, a face of a non-array cube
            errors.push_back("imageSize: mip " + std::to_string(mip) + " holds " + std::to_string(imageSize) + " bytes, not " +
                             std::to_string(faceBytes));
        offset += 4 + faces * padded(faceBytes);
        offset = padded(offset);
    }
    if (offset != file.size())
        errors.push_back("file size: " + std::to_string(file.size()) + " bytes where the levels end at " + std::to_string(offset));
    return errors;
}

} // namespace iblkit::testing
