#include "ktx2_validator.hpp"
#include "violations.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <map>
#include <numeric>
#include <set>

namespace iblkit::testing {
namespace {

// --- What the specification says, restated here on purpose rather than shared with the writer.

constexpr uint8_t kFileIdentifier[12] = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};
constexpr uint64_t kHeaderAndIndexBytes = 80, kLevelEntryBytes = 24;

struct FormatFacts {
    uint32_t channels, bitsPerChannel;
    uint32_t texelBytes() const { return channels * bitsPerChannel / 8; }
};
// VkFormat -> its channels; every one an SFLOAT format with channels in R, G, B, A order.
const std::map<uint32_t, FormatFacts> kFormats = {{97, {4, 16}}, {109, {4, 32}}, {83, {2, 16}}, {103, {2, 32}}};

// Khronos Data Format Specification 1.3.
constexpr uint32_t kDfVersion13 = 2, kModelRgbsda = 1, kPrimariesBt709 = 1, kTransferLinear = 1;
constexpr uint32_t kChannelIdOfSample[4] = {0, 1, 2, 15};
constexpr uint32_t kQualifiersFloatSigned = 0x8 | 0x4; // the top four bits of channelType: F, S, E, L

// The keys this specification version defines; others starting with KTX or ktx are reserved.
const std::set<std::string> kDefinedKtxKeys = {"KTXcubemapIncomplete", "KTXorientation", "KTXglFormat",
                                               "KTXdxgiFormat__",      "KTXmetalPixelFormat", "KTXswizzle",
                                               "KTXwriter",            "KTXwriterScParams", "KTXastcDecodeMode",
                                               "KTXanimData"};

// --- Reading.

class File {
public:
    explicit File(std::span<const std::byte> bytes) : bytes_(bytes) {}
    bool has(uint64_t offset, uint64_t length) const { return offset <= bytes_.size() && length <= bytes_.size() - offset; }
    uint8_t u8(uint64_t offset) const { return has(offset, 1) ? uint8_t(bytes_[offset]) : 0; }
    uint32_t u32(uint64_t offset) const { return uint32_t(little(offset, 4)); }
    uint64_t u64(uint64_t offset) const { return little(offset, 8); }
    uint64_t size() const { return bytes_.size(); }

private:
    uint64_t little(uint64_t offset, int width) const {
        uint64_t value = 0;
        for (int i = width - 1; i >= 0; --i) value = (value << 8) | u8(offset + uint64_t(i));
        return value;
    }
    std::span<const std::byte> bytes_;
};

std::string number(uint64_t value) { return std::to_string(value); }

struct Header {
    uint32_t vkFormat, typeSize, width, height, depth, layers, faces, levels, scheme;
    uint32_t dfdOffset, dfdLength, kvdOffset, kvdLength;
    uint64_t sgdOffset, sgdLength;
    uint32_t levelEntries() const { return std::max(1u, levels); }
    uint64_t levelIndexEnd() const { return kHeaderAndIndexBytes + kLevelEntryBytes * levelEntries(); }
};

Header readHeader(const File& file) {
    const auto at = [&](uint64_t offset) { return file.u32(offset); };
    return {at(12), at(16), at(20), at(24), at(28), at(32), at(36), at(40), at(44),
            at(48), at(52), at(56), at(60), file.u64(64), file.u64(72)};
}

// --- The rules, section by section.

void checkHeader(const Header& h, const FormatFacts& format, Violations& v) {
    v.expect(h.typeSize == format.bitsPerChannel / 8, "typeSize: must be " + number(format.bitsPerChannel / 8) +
                                                          " for vkFormat " + number(h.vkFormat) + ", is " + number(h.typeSize));
    v.expect(h.width > 0, "pixelWidth: must not be 0");
    v.expect(h.height > 0, "pixelHeight: must not be 0 for a 2D texture or cube");
    v.expect(h.depth == 0, "pixelDepth: must be 0 for a 2D texture or cube, is " + number(h.depth));
    v.expect(h.layers == 0, "layerCount: must be 0 for a texture that is not an array, is " + number(h.layers));
    v.expect(h.faces == 1 || h.faces == 6, "faceCount: must be 1 or 6, is " + number(h.faces));
    if (h.faces == 6) v.expect(h.width == h.height, "pixelHeight: must equal pixelWidth for a cube");
    const uint32_t maxLevels = uint32_t(std::bit_width(std::max(h.width, h.height)));
    v.expect(h.levels <= maxLevels, "levelCount: " + number(h.levels) + " exceeds the " + number(maxLevels) +
                                        " levels down to 1x1");
    v.expect(h.scheme == 0, "supercompressionScheme: must be 0 (this validator covers files without supercompression), is " +
                                number(h.scheme));
}

void checkIndex(const File& file, const Header& h, Violations& v) {
    v.expect(file.has(kHeaderAndIndexBytes, kLevelEntryBytes * h.levelEntries()), "level index: lies outside the file");
    v.expect(h.dfdOffset == h.levelIndexEnd(), "dfdByteOffset: the DFD must follow the level index, at " +
                                                   number(h.levelIndexEnd()) + ", is " + number(h.dfdOffset));
    v.expect(file.has(h.dfdOffset, h.dfdLength), "dfdByteLength: the DFD lies outside the file");
    if (h.kvdLength == 0) {
        v.expect(h.kvdOffset == 0, "kvdByteOffset: must be 0 when kvdByteLength is 0");
    } else {
        v.expect(h.kvdOffset == uint64_t(h.dfdOffset) + h.dfdLength,
                 "kvdByteOffset: the key/value data must follow the DFD (dfdTotalSize = kvdByteOffset - dfdByteOffset)");
        v.expect(file.has(h.kvdOffset, h.kvdLength), "kvdByteLength: the key/value data lie outside the file");
    }
    v.expect(h.sgdOffset == 0 && h.sgdLength == 0, "sgdByteOffset/sgdByteLength: must be 0 without supercompression");
}

void checkSample(const File& file, uint64_t sample, uint32_t index, const FormatFacts& format, Violations& v) {
    const std::string which = "DFD sample " + number(index) + ": ";
    const uint32_t word = file.u32(sample);
    v.expect((word & 0xFFFF) == index * format.bitsPerChannel, which + "bitOffset must be " + number(index * format.bitsPerChannel));
    v.expect(((word >> 16) & 0xFF) == format.bitsPerChannel - 1, which + "bitLength must be " + number(format.bitsPerChannel - 1));
    v.expect(((word >> 24) & 0xF) == kChannelIdOfSample[index], which + "channelType must be " + number(kChannelIdOfSample[index]));
    v.expect((word >> 28) == kQualifiersFloatSigned, which + "qualifiers must be FLOAT | SIGNED");
    v.expect(file.u32(sample + 4) == 0, which + "samplePosition must be 0");
    v.expect(file.u32(sample + 8) == std::bit_cast<uint32_t>(-1.0f), which + "sampleLower must be -1.0f for SFLOAT");
    v.expect(file.u32(sample + 12) == std::bit_cast<uint32_t>(1.0f), which + "sampleUpper must be 1.0f for SFLOAT");
}

void checkDfd(const File& file, const Header& h, const FormatFacts& format, Violations& v) {
    const uint64_t at = h.dfdOffset, block = at + 4;
    const uint32_t blockSize = file.u32(block + 4) >> 16, expectedBlockSize = 24 + 16 * format.channels;
    v.expect(file.u32(at) == h.dfdLength, "dfdTotalSize: must equal dfdByteLength");
    v.expect(file.u32(block) == 0, "DFD: the descriptor block must be Khronos' (vendorId 0) basic one (descriptorType 0)");
    v.expect((file.u32(block + 4) & 0xFFFF) == kDfVersion13, "DFD versionNumber: must be 2 (KDF 1.3)");
    v.expect(blockSize == expectedBlockSize, "DFD descriptorBlockSize: must be 24 + 16 per sample = " + number(expectedBlockSize));
    v.expect(h.dfdLength == 4 + expectedBlockSize, "dfdByteLength: must hold dfdTotalSize and one basic block");
    const uint32_t model = file.u32(block + 8);
    v.expect((model & 0xFF) == kModelRgbsda, "DFD colorModel: must be KHR_DF_MODEL_RGBSDA");
    v.expect(((model >> 8) & 0xFF) == kPrimariesBt709, "DFD colorPrimaries: must be BT709");
    v.expect(((model >> 16) & 0xFF) == kTransferLinear, "DFD transferFunction: must be LINEAR for float data");
    v.expect((model >> 24) == 0, "DFD flags: must be ALPHA_STRAIGHT (0)");
    v.expect(file.u32(block + 12) == 0, "DFD texelBlockDimension: must be 1x1x1x1 (stored as 0)");
    v.expect(file.u32(block + 16) == format.texelBytes(), "DFD bytesPlane0: must be the texel size " + number(format.texelBytes()) +
                                                             ", bytesPlane1..3 0");
    v.expect(file.u32(block + 20) == 0, "DFD bytesPlane4..7: must be 0");
    for (uint32_t s = 0; s < format.channels; ++s) checkSample(file, block + 24 + 16 * uint64_t(s), s, format, v);
}

struct KeyValue {
    std::string key, value;
};

// Walks the entries, checking each one's framing; returns what it could read.
std::vector<KeyValue> readKeyValues(const File& file, const Header& h, Violations& v) {
    std::vector<KeyValue> entries;
    const uint64_t end = uint64_t(h.kvdOffset) + h.kvdLength;
    uint64_t at = h.kvdOffset;
    while (at < end) {
        const uint32_t length = file.u32(at);
        if (at + 4 > end || length < 2 || at + 4 + length > end) {
            v.expect(false, "keyAndValueByteLength: entry at " + number(at) + " is shorter than 2 or runs past kvdByteLength");
            return entries;
        }
        std::string bytes;
        for (uint64_t i = 0; i < length; ++i) bytes.push_back(char(file.u8(at + 4 + i)));
        const size_t nul = bytes.find('\0');
        v.expect(nul != std::string::npos && nul > 0, "keyAndValue: the key at " + number(at) + " must be non-empty and NUL-terminated");
        if (nul == std::string::npos) return entries;
        entries.push_back({bytes.substr(0, nul), bytes.substr(nul + 1)});
        at += 4 + length;
        for (; at % 4 != 0; ++at) v.expect(at < end && file.u8(at) == 0, "valuePadding: must be 0x00 bytes up to a multiple of 4 inside kvdByteLength");
    }
    v.expect(at == end, "kvdByteLength: must equal the sum of the padded entries");
    return entries;
}

void checkKeyValueData(const File& file, const Header& h, Violations& v) {
    const auto entries = readKeyValues(file, h, v);
    bool writer = false;
    for (size_t i = 0; i < entries.size(); ++i) {
        const auto& [key, value] = entries[i];
        if (i > 0) v.expect(entries[i - 1].key < key, "key/value data: keys must be sorted by code point and unique ('" +
                                                          entries[i - 1].key + "' before '" + key + "')");
        const bool reserved = key.starts_with("KTX") || key.starts_with("ktx");
        v.expect(!reserved || kDefinedKtxKeys.count(key), "key/value data: '" + key + "' uses the reserved KTX prefix");
        if (key == "KTXwriter") {
            writer = true;
            v.expect(value.size() >= 2 && value.back() == '\0' && value.find('\0') == value.size() - 1,
                     "KTXwriter: the value must be a non-empty NUL-terminated string");
        }
    }
    v.expect(writer, "KTXwriter: the key/value data must name the writer");
}

void checkLevels(const File& file, const Header& h, const FormatFacts& format, Violations& v) {
    const uint64_t alignment = std::lcm(uint64_t(format.texelBytes()), uint64_t(4));
    uint64_t previousEnd = h.kvdLength ? uint64_t(h.kvdOffset) + h.kvdLength : uint64_t(h.dfdOffset) + h.dfdLength;
    for (uint32_t level = h.levelEntries(); level-- > 0;) { // stored smallest first
        const uint64_t entry = kHeaderAndIndexBytes + kLevelEntryBytes * level;
        const uint64_t offset = file.u64(entry), length = file.u64(entry + 8), uncompressed = file.u64(entry + 16);
        const uint64_t expected = uint64_t(h.faces) * std::max(1u, h.width >> level) * std::max(1u, h.height >> level) *
                                  format.texelBytes();
        const uint64_t padded = (previousEnd + alignment - 1) / alignment * alignment;
        const std::string which = "level " + number(level) + ": ";
        v.expect(length == expected, which + "byteLength must be faces x width x height x texel size = " + number(expected) +
                                         ", is " + number(length));
        v.expect(uncompressed == length, which + "uncompressedByteLength must equal byteLength without supercompression");
        v.expect(offset % alignment == 0, which + "byteOffset must be a multiple of lcm(texel size, 4) = " + number(alignment));
        v.expect(offset == padded, which + "byteOffset must directly follow the smaller level (or the key/value data) "
                                           "after mipPadding, at " + number(padded) + ", is " + number(offset));
        for (uint64_t at = previousEnd; at < std::min(offset, padded); ++at)
            v.expect(file.u8(at) == 0, which + "mipPadding must be 0x00 bytes");
        v.expect(file.has(offset, length), which + "lies outside the file");
        previousEnd = offset + length;
    }
    v.expect(previousEnd == file.size(), "file size: the file must end with level 0, at " + number(previousEnd) +
                                             ", is " + number(file.size()) + " bytes");
}

} // namespace

std::vector<std::string> validateKtx2(std::span<const std::byte> bytes) {
    const File file(bytes);
    if (bytes.size() < kHeaderAndIndexBytes)
        return {"header: the file has " + number(bytes.size()) + " bytes, fewer than the 80 of the header and index"};
    if (std::memcmp(bytes.data(), kFileIdentifier, sizeof kFileIdentifier) != 0)
        return {"identifier: the file does not start with the KTX 2.0 identifier"};
    const Header header = readHeader(file);
    const auto format = kFormats.find(header.vkFormat);
    if (format == kFormats.end()) return {"vkFormat: " + number(header.vkFormat) + " is not one this validator checks"};
    Violations violations;
    checkHeader(header, format->second, violations);
    checkIndex(file, header, violations);
    checkDfd(file, header, format->second, violations);
    checkKeyValueData(file, header, violations);
    // A level count the index cannot hold is reported above; its levels cannot be checked.
    if (header.levelEntries() <= 32 && file.has(kHeaderAndIndexBytes, kLevelEntryBytes * header.levelEntries()))
        checkLevels(file, header, format->second, violations);
    return violations.take();
}

} // namespace iblkit::testing
