#include "byte_io.hpp"
#include "ktx2.hpp"
#include "ktx2_format.hpp"
#include "texture_shape.hpp"

#include <algorithm>
#include <cstring>
#include <map>

#include <numeric>
#include <vector>

namespace iblkit::image_io {
namespace {

using namespace ktx2;

// Formats an environment or LUT file might arrive in, named so a refusal says what the file is.
std::string vkFormatDescription(uint32_t vkFormat) {
    static const std::map<uint32_t, const char*> names = {
        {0, "UNDEFINED, e.g. Basis Universal"}, {37, "R8G8B8A8_UNORM"}, {43, "R8G8B8A8_SRGB"},
        {44, "B8G8R8A8_UNORM"}, {50, "B8G8R8A8_SRGB"}, {64, "A2B10G10R10_UNORM_PACK32"},
        {76, "R16_SFLOAT"}, {90, "R16G16B16_SFLOAT"}, {100, "R32_SFLOAT"}, {106, "R32G32B32_SFLOAT"},
        {122, "B10G11R11_UFLOAT_PACK32"}, {123, "E5B9G9R9_UFLOAT_PACK32"}, {131, "BC1_RGB_UNORM_BLOCK"},
        {143, "BC6H_UFLOAT_BLOCK"}, {144, "BC6H_SFLOAT_BLOCK"}, {145, "BC7_UNORM_BLOCK"}, {146, "BC7_SRGB_BLOCK"}};
    const auto name = names.find(vkFormat);
    return std::to_string(vkFormat) + (name == names.end() ? "" : std::string(" (") + name->second + ")");
}

std::string schemeDescription(uint32_t scheme) {
    static const std::map<uint32_t, const char*> names = {{1, "BasisLZ"}, {2, "Zstandard"}, {3, "ZLIB"}};
    const auto name = names.find(scheme);
    return std::to_string(scheme) + (name == names.end() ? "" : std::string(" (") + name->second + ")");
}

std::string supportedFormats() {
    std::string list;
    for (auto format : {PixelFormat::Rgba16Float, PixelFormat::Rgba32Float, PixelFormat::Rg16Float, PixelFormat::Rg32Float})
        list += (list.empty() ? "" : ", ") + std::to_string(vkFormatOf(format)) + " (" +
                std::string(vulkanFormatName(format)) + ")";
    return list;
}

void requireIdentifier(const ByteReader& in) {
    const auto identifier = in.slice(0, kIdentifier.size(), "the identifier");
    if (!std::equal(kIdentifier.begin(), kIdentifier.end(), identifier.begin(),
                    [](uint8_t expected, std::byte actual) { return uint8_t(actual) == expected; }))
        in.fail("is not a KTX 2.0 file (its first 12 bytes are not the KTX 2.0 identifier)");
}

PixelFormat readFormat(const ByteReader& in) {
    const uint32_t vkFormat = in.get<uint32_t>(kVkFormat, "the header");
    const auto format = formatOfVkFormat(vkFormat);
    if (!format) in.fail("has vkFormat " + vkFormatDescription(vkFormat) + "; supported: " + supportedFormats());
    const uint32_t typeSize = in.get<uint32_t>(kTypeSize, "the header");
    if (typeSize != bytesPerChannel(*format))
        in.fail("has typeSize " + std::to_string(typeSize) + "; " + std::string(vulkanFormatName(*format)) + " needs " +
                std::to_string(bytesPerChannel(*format)));
    return *format;
}

// The header's fields, refusing every kind of texture the kit does not read.
Texture readHeader(const ByteReader& in) {
    const auto field = [&](size_t offset) { return in.get<uint32_t>(offset, "the header"); };
    const auto number = [&](size_t offset) { return std::to_string(field(offset)); };
    const PixelFormat format = readFormat(in);
    const char* only2D = "only 2D textures and cubes are supported";
    if (field(kSupercompressionScheme) != 0)
        in.fail("is supercompressed with scheme " + schemeDescription(field(kSupercompressionScheme)) +
                "; only files without supercompression (scheme 0) are supported");
    if (field(kPixelDepth) != 0) in.fail("is a 3D texture (pixelDepth " + number(kPixelDepth) + "); " + only2D);
    if (field(kLayerCount) != 0)
        in.fail("is an array texture (layerCount " + number(kLayerCount) + "); arrays are not supported");
    if (field(kPixelWidth) != 0 && field(kPixelHeight) == 0)
        in.fail(std::string("is a 1D texture (pixelHeight 0); ") + only2D);
    // levelCount 0 asks the loader to make the mips; the file holds the base level only.
    Texture texture{format, field(kPixelWidth), field(kPixelHeight), field(kFaceCount), std::max(1u, field(kLevelCount)), {}};
    const auto problem = shapeProblem(texture.width, texture.height, texture.faces, texture.mips);
    if (!problem.empty()) in.fail(problem);
    return texture;
}

// The DFD and key/value data are not interpreted (vkFormat says everything), but an index that
// points outside the file is a truncated or corrupt file.
void requireIndexInsideFile(const ByteReader& in, size_t levelIndexEnd) {
    const auto field = [&](size_t offset) { return in.get<uint32_t>(offset, "the index"); };
    const uint32_t dfdOffset = field(kDfdByteOffset), dfdLength = field(kDfdByteLength);
    if (dfdOffset < levelIndexEnd || dfdLength < 4)
        in.fail("has a corrupt index: the Data Format Descriptor (" + std::to_string(dfdLength) + " bytes at " +
                std::to_string(dfdOffset) + ") overlaps the header or is too short");
    in.require(dfdOffset, dfdLength, "the Data Format Descriptor");
    if (in.get<uint32_t>(dfdOffset, "the Data Format Descriptor") != dfdLength)
        in.fail("has a corrupt index: dfdTotalSize differs from dfdByteLength");
    if (field(kKvdByteLength) != 0) in.require(field(kKvdByteOffset), field(kKvdByteLength), "the key/value data");
    if (field(kKvdByteLength) == 0 && field(kKvdByteOffset) != 0)
        in.fail("has a corrupt index: kvdByteOffset is " + std::to_string(field(kKvdByteOffset)) +
                " with no key/value data (the specification requires 0)");
    if (in.get<uint64_t>(kSgdByteLength, "the index") != 0)
        in.fail("has a corrupt index: supercompression global data without supercompression");
    if (in.get<uint64_t>(kSgdByteOffset, "the index") != 0)
        in.fail("has a corrupt index: sgdByteOffset is " + std::to_string(in.get<uint64_t>(kSgdByteOffset, "the index")) +
                " with no supercompression global data (the specification requires 0)");
}

// The specification's rules on the levels' places: each offset a multiple of lcm(texel size, 4),
// and no two levels sharing a byte.
void requireLevelsApartAndAligned(const ByteReader& in, const Texture& texture) {
    const uint64_t texel = bytesPerTexel(texture.format);
    const uint64_t alignment = std::lcm(texel, uint64_t(4));
    std::vector<std::pair<uint64_t, uint64_t>> ranges;
    for (uint32_t mip = 0; mip < texture.mips; ++mip) {
        const size_t entry = kLevelIndex + kLevelIndexEntry * mip;
        const uint64_t offset = in.get<uint64_t>(entry, "the level index"), length = in.get<uint64_t>(entry + 8, "the level index");
        if (offset % alignment != 0)
            in.fail("has a corrupt level index: level " + std::to_string(mip) + " starts at " + std::to_string(offset) +
                    ", not a multiple of " + std::to_string(alignment) + " (the specification aligns levels to lcm(texel size, 4))");
        ranges.emplace_back(offset, length);
    }
    for (size_t a = 0; a < ranges.size(); ++a)
        for (size_t b = a + 1; b < ranges.size(); ++b)
            if (ranges[a].first < ranges[b].first + ranges[b].second && ranges[b].first < ranges[a].first + ranges[a].second)
                in.fail("has a corrupt level index: levels " + std::to_string(a) + " and " + std::to_string(b) + " overlap");
}

std::vector<std::byte> readLevel(const ByteReader& in, const Texture& texture, uint32_t mip, size_t levelIndexEnd) {
    const size_t entry = kLevelIndex + kLevelIndexEntry * mip;
    const auto field = [&](size_t offset) { return in.get<uint64_t>(offset, "the level index"); };
    const uint64_t offset = field(entry), length = field(entry + 8), uncompressed = field(entry + 16);
    const uint64_t expected = texture.faceBytes(mip) * texture.faces;
    const std::string level = "level " + std::to_string(mip);
    if (length != expected || uncompressed != expected)
        in.fail("has a corrupt level index: " + level + " has byteLength " + std::to_string(length) +
                " and uncompressedByteLength " + std::to_string(uncompressed) + "; its size needs " +
                std::to_string(expected));
    if (offset < levelIndexEnd) in.fail("has a corrupt level index: " + level + " starts inside the header");
    const auto data = in.slice(offset, length, level);
    return {data.begin(), data.end()};
}

} // namespace

Texture decodeKtx2(std::span<const std::byte> bytes, const std::string& name) {
    const ByteReader in(bytes, name);
    requireIdentifier(in);
    Texture texture = readHeader(in);
    const size_t levelIndexEnd = kLevelIndex + kLevelIndexEntry * texture.mips;
    in.require(kLevelIndex, levelIndexEnd - kLevelIndex, "the level index");
    requireIndexInsideFile(in, levelIndexEnd);
    for (uint32_t mip = 0; mip < texture.mips; ++mip)
        texture.levels.push_back(readLevel(in, texture, mip, levelIndexEnd));
    requireLevelsApartAndAligned(in, texture);
    return texture;
}

std::map<std::string, std::string> decodeKtx2KeyValues(std::span<const std::byte> bytes, const std::string& name) {
    const ByteReader in(bytes, name);
    requireIdentifier(in);
    const uint32_t offset = in.get<uint32_t>(kKvdByteOffset, "the index"), length = in.get<uint32_t>(kKvdByteLength, "the index");
    const auto data = in.slice(offset, length, "the key/value data");
    std::map<std::string, std::string> entries;
    for (size_t at = 0; at + 4 <= data.size();) {
        uint32_t entryLength = 0;
        std::memcpy(&entryLength, data.data() + at, 4);
        if (entryLength > data.size() - at - 4) in.fail("has a corrupt key/value entry at byte " + std::to_string(offset + at));
        const std::string entry(reinterpret_cast<const char*>(data.data() + at + 4), entryLength);
        const size_t nul = entry.find('\0');
        if (nul == std::string::npos) in.fail("has a key/value entry without a NUL after its key");
        std::string value = entry.substr(nul + 1);
        if (!value.empty() && value.back() == '\0') value.pop_back();
        entries[entry.substr(0, nul)] = std::move(value);
        at += 4 + (entryLength + 3) / 4 * 4;
    }
    return entries;
}

} // namespace iblkit::image_io
