// The KTX2 validator must be able to fail: every rule it checks, broken on purpose in an
// otherwise conforming file, is reported by the field it is about.
#include "image_io_test_support.hpp"
#include "ktx2.hpp"
#include "ktx2_validator.hpp"

#include <gtest/gtest.h>

namespace iblkit::testing {
namespace {

using image_io::PixelFormat;

// The same small cube as the KTX2 layout tests: DFD at 152, key/value data at 244 (32 bytes),
// levels 2, 1, 0 at 280, 328 and 520, 1288 bytes in all.
std::vector<std::byte> goodKtx2File() {
    return image_io::encodeKtx2(patternedTexture(PixelFormat::Rgba16Float, 4, 4, 6, 3), "iblkit 0.1.0-dev");
}

// The file with its 32 bytes of key/value data replaced (keys and values NUL-terminated inside
// `entries`, lengths and padding added here).
std::vector<std::byte> withKeyValues(const std::vector<std::string>& entries) {
    std::vector<std::byte> kvd;
    for (const auto& entry : entries) {
        const auto length = uint32_t(entry.size());
        const auto* bytes = reinterpret_cast<const std::byte*>(&length);
        kvd.insert(kvd.end(), bytes, bytes + 4);
        for (char c : entry) kvd.push_back(std::byte(c));
        while (kvd.size() % 4) kvd.push_back(std::byte{0});
    }
    EXPECT_EQ(kvd.size(), 32u) << "the replacement must keep the file's layout";
    auto file = goodKtx2File();
    std::copy(kvd.begin(), kvd.end(), file.begin() + 244);
    return file;
}

// The levels stored largest first, the index pointing at them correctly.
std::vector<std::byte> largestLevelFirst() {
    const auto good = goodKtx2File();
    auto file = prefix(good, 280);
    const size_t levels[3][2] = {{520, 768}, {328, 192}, {280, 48}};
    for (int level = 0; level < 3; ++level) {
        const auto offset = uint64_t(file.size());
        file.insert(file.end(), good.begin() + std::ptrdiff_t(levels[level][0]),
                    good.begin() + std::ptrdiff_t(levels[level][0] + levels[level][1]));
        file = poked(file, 80 + 24 * size_t(level), offset);
    }
    return file;
}

struct BrokenKtx2 {
    std::string what;
    std::vector<std::byte> file;
    std::string reported;
};

std::vector<BrokenKtx2> brokenKtx2Files() {
    const auto good = goodKtx2File();
    auto longer = good;
    longer.push_back(std::byte{0});
    return {
        {"short file", prefix(good, 79), "header:"},
        {"identifier", poked<uint8_t>(good, 1, 'k'), "identifier:"},
        {"unknown vkFormat", poked<uint32_t>(good, 12, 98), "vkFormat:"},
        {"typeSize", poked<uint32_t>(good, 16, 4), "typeSize:"},
        {"pixelHeight of a cube", poked<uint32_t>(good, 24, 2), "pixelHeight: must equal pixelWidth"},
        {"pixelDepth", poked<uint32_t>(good, 28, 1), "pixelDepth:"},
        {"layerCount", poked<uint32_t>(good, 32, 6), "layerCount:"},
        {"faceCount", poked<uint32_t>(good, 36, 2), "faceCount:"},
        {"levelCount", poked<uint32_t>(good, 40, 4), "levelCount:"},
        {"supercompressionScheme", poked<uint32_t>(good, 44, 2), "supercompressionScheme:"},
        {"dfdByteOffset", poked<uint32_t>(good, 48, 156), "dfdByteOffset:"},
        {"dfdByteLength", poked<uint32_t>(good, 52, 96), "dfdTotalSize: must equal dfdByteLength"},
        {"kvdByteOffset", poked<uint32_t>(good, 56, 248), "kvdByteOffset:"},
        {"kvdByteLength 0 with an offset", poked<uint32_t>(good, 60, 0), "kvdByteOffset: must be 0"},
        {"sgdByteLength", poked<uint64_t>(good, 72, 8), "sgdByteOffset/sgdByteLength:"},
        {"dfdTotalSize", poked<uint32_t>(good, 152, 96), "dfdTotalSize:"},
        {"vendorId", poked<uint32_t>(good, 156, 1), "vendorId"},
        {"versionNumber", poked<uint16_t>(good, 160, 1), "versionNumber:"},
        {"descriptorBlockSize", poked<uint16_t>(good, 162, 72), "descriptorBlockSize:"},
        {"colorModel YUVSDA", poked<uint8_t>(good, 164, 2), "colorModel:"},
        {"colorPrimaries", poked<uint8_t>(good, 165, 2), "colorPrimaries:"},
        {"transferFunction sRGB", poked<uint8_t>(good, 166, 2), "transferFunction:"},
        {"premultiplied alpha", poked<uint8_t>(good, 167, 1), "DFD flags:"},
        {"texelBlockDimension", poked<uint8_t>(good, 168, 3), "texelBlockDimension:"},
        {"bytesPlane0", poked<uint8_t>(good, 172, 16), "bytesPlane0:"},
        {"sample 2 bitLength", poked<uint8_t>(good, 180 + 32 + 2, 31), "DFD sample 2: bitLength"},
        {"sample 1 channel", poked<uint8_t>(good, 180 + 16 + 3, 0xC2), "DFD sample 1: channelType"},
        {"sample 0 not FLOAT", poked<uint8_t>(good, 180 + 3, 0x40), "DFD sample 0: qualifiers"},
        {"sample 3 bitOffset", poked<uint16_t>(good, 180 + 48, 40), "DFD sample 3: bitOffset"},
        {"sample 0 sampleLower", poked<uint32_t>(good, 180 + 8, 0), "DFD sample 0: sampleLower"},
        {"sample 3 sampleUpper", poked<float>(good, 180 + 48 + 12, 65504.f), "DFD sample 3: sampleUpper"},
        {"keyAndValueByteLength", poked<uint32_t>(good, 244, 40), "keyAndValueByteLength:"},
        {"valuePadding", poked<uint8_t>(good, 275, 1), "valuePadding:"},
        {"KTXwriter without NUL", poked<uint8_t>(good, 274, '!'), "KTXwriter: the value must be"},
        {"no KTXwriter", poked<uint8_t>(good, 256, 'x'), "KTXwriter: the key/value data must name the writer"},
        {"reserved key", poked<uint8_t>(good, 256, 'x'), "reserved KTX prefix"},
        {"unsorted keys", withKeyValues({std::string("b\0x\0", 4), std::string("KTXwriter\0abcdefg\0", 18)}), "sorted"},
        {"level 0 byteLength", poked<uint64_t>(good, 88, 767), "level 0: byteLength"},
        {"level 1 uncompressedByteLength", poked<uint64_t>(good, 120, 0), "level 1: uncompressedByteLength"},
        {"level 2 misaligned", poked<uint64_t>(good, 128, 276), "level 2: byteOffset must be a multiple of lcm(texel size, 4) = 8"},
        {"a gap before level 1", poked<uint64_t>(good, 104, 336), "level 1: byteOffset must directly follow"},
        {"levels overlapping", poked<uint64_t>(good, 104, 320), "level 1: byteOffset must directly follow"},
        {"largest level first", largestLevelFirst(), "level 2: byteOffset must directly follow"},
        {"mipPadding", poked<uint8_t>(good, 277, 1), "level 2: mipPadding"},
        {"truncated", prefix(good, good.size() - 1), "level 0: lies outside the file"},
        {"trailing byte", longer, "file size: the file must end with level 0"},
    };
}

TEST(ImageIoKtx2Validator, FindsNothingWrongWithAConformingFile) {
    EXPECT_EQ(validateKtx2(goodKtx2File()), std::vector<std::string>{});
    EXPECT_EQ(validateKtx2(withKeyValues({std::string("KTXwriter\0abcdefg\0", 18), std::string("b\0x\0", 4)})),
              std::vector<std::string>{});
}

TEST(ImageIoKtx2Validator, ReportsEachBrokenRuleByItsField) {
    for (const auto& broken : brokenKtx2Files()) {
        const auto violations = validateKtx2(broken.file);
        EXPECT_TRUE(mentions(violations, broken.reported))
            << broken.what << ": expected a violation mentioning \"" << broken.reported << "\", got "
            << ::testing::PrintToString(violations);
    }
}

} // namespace
} // namespace iblkit::testing
