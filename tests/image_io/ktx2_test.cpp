// The KTX2 writer checked byte by byte against the specification on one small cube, and the
// reader refusing every kind of file it does not read with one line and never a crash.
#include "image_io_test_support.hpp"
#include "ktx2.hpp"

#include <gtest/gtest.h>

namespace iblkit::image_io {
namespace {

using testing::imageErrorOf;
using testing::peek32;
using testing::peek64;
using testing::poked;

// A 4x4 RGBA16F cube with 3 mips, its KTXwriter chosen so the key/value data end 4 bytes short
// of the 8-byte level alignment.
std::vector<std::byte> smallKtx2Cube() {
    return encodeKtx2(testing::patternedTexture(PixelFormat::Rgba16Float, 4, 4, 6, 3), "iblkit 0.1.0-dev");
}

std::string ktx2Error(const std::vector<std::byte>& bytes) {
    return imageErrorOf([&] { decodeKtx2(bytes, "bad.ktx2"); });
}

TEST(ImageIoKtx2, HeaderAndIndexOfASmallCube) {
    const auto file = smallKtx2Cube();
    const uint8_t identifier[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32, 0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
    EXPECT_EQ(std::memcmp(file.data(), identifier, 12), 0);
    // vkFormat, typeSize, pixelWidth, pixelHeight, pixelDepth, layerCount, faceCount, levelCount, supercompressionScheme
    const uint32_t header[9] = {97, 2, 4, 4, 0, 0, 6, 3, 0};
    for (int i = 0; i < 9; ++i) EXPECT_EQ(peek32(file, 12 + 4 * i), header[i]) << "header field " << i;
    // The DFD follows the 3-entry level index at 80 + 3 * 24; 4 + 24 + 4 * 16 bytes for four samples.
    EXPECT_EQ(peek32(file, 48), 152u);
    EXPECT_EQ(peek32(file, 52), 92u);
    EXPECT_EQ(peek32(file, 56), 244u);
    EXPECT_EQ(peek32(file, 60), 32u); // 4 + "KTXwriter\0" + "iblkit 0.1.0-dev\0" = 31, padded to 32
    EXPECT_EQ(peek64(file, 64), 0u);
    EXPECT_EQ(peek64(file, 72), 0u);
}

TEST(ImageIoKtx2, LevelsAreStoredSmallestFirstAndAligned) {
    const auto file = smallKtx2Cube();
    // The key/value data end at 276; level 2 (6 faces of 1x1x8 bytes) starts at the next
    // multiple of 8, level 1 (6 x 2x2x8) and level 0 (6 x 4x4x8) follow it, and the file ends.
    const uint64_t expected[3][2] = {{520, 768}, {328, 192}, {280, 48}};
    for (int level = 0; level < 3; ++level) {
        EXPECT_EQ(peek64(file, 80 + 24 * level), expected[level][0]) << "byteOffset of level " << level;
        EXPECT_EQ(peek64(file, 88 + 24 * level), expected[level][1]) << "byteLength of level " << level;
        EXPECT_EQ(peek64(file, 96 + 24 * level), expected[level][1]) << "uncompressedByteLength of level " << level;
    }
    EXPECT_EQ(peek32(file, 276), 0u) << "mipPadding";
    EXPECT_EQ(file.size(), 1288u);
}

// What KTX-Software's createDFDUnpacked(0, 4, 2, 0, s_SFLOAT) writes for R16G16B16A16_SFLOAT.
TEST(ImageIoKtx2, DataFormatDescriptorOfRgba16Float) {
    const auto file = smallKtx2Cube();
    const uint32_t expected[] = {
        92,                            // dfdTotalSize
        0,                             // vendorId Khronos, descriptorType basic
        2 | (88u << 16),               // versionNumber 1.3, descriptorBlockSize 24 + 4 x 16
        1 | (1u << 8) | (1u << 16),    // RGBSDA, BT709, LINEAR, straight alpha
        0,                             // texel block 1x1x1x1
        8, 0,                          // bytesPlane0 = 8
        0 | (15u << 16) | (0xC0u << 24), 0, 0xBF800000, 0x3F800000,  // R: FLOAT|SIGNED, -1.0 to 1.0
        16 | (15u << 16) | (0xC1u << 24), 0, 0xBF800000, 0x3F800000, // G
        32 | (15u << 16) | (0xC2u << 24), 0, 0xBF800000, 0x3F800000, // B
        48 | (15u << 16) | (0xCFu << 24), 0, 0xBF800000, 0x3F800000, // A (channel id 15)
    };
    for (size_t i = 0; i < std::size(expected); ++i) EXPECT_EQ(peek32(file, 152 + 4 * i), expected[i]) << "DFD word " << i;
}

TEST(ImageIoKtx2, KeyValueDataNameTheWriter) {
    const auto file = smallKtx2Cube();
    EXPECT_EQ(peek32(file, 244), 27u);
    const std::string entry(reinterpret_cast<const char*>(file.data()) + 248, 28);
    EXPECT_EQ(entry, std::string("KTXwriter\0iblkit 0.1.0-dev\0\0", 28));
}

TEST(ImageIoKtx2, CubeFacesFollowEachOtherInTheirOrder) {
    std::vector<float> values;
    for (int face = 0; face < 6; ++face) values.insert(values.end(), 2 * 2 * 2, float(face + 1));
    const auto file = encodeKtx2(makeTexture(PixelFormat::Rg32Float, 2, 2, 6, 1, values), "w");
    const uint64_t level0 = peek64(file, 80);
    for (int face = 0; face < 6; ++face) {
        float first;
        std::memcpy(&first, file.data() + level0 + face * 2 * 2 * 8, 4);
        EXPECT_EQ(first, float(face + 1)) << "face " << face;
    }
}

TEST(ImageIoKtx2Reader, LevelCountZeroMeansTheBaseLevelOnly) {
    const auto file = smallKtx2Cube();
    const auto texture = decodeKtx2(poked<uint32_t>(file, 40, 0), "base.ktx2");
    EXPECT_EQ(texture.mips, 1u);
    ASSERT_EQ(texture.levels.size(), 1u);
    EXPECT_TRUE(texture.levels[0] == decodeKtx2(file, "whole.ktx2").levels[0]);
}

TEST(ImageIoKtx2Reader, RefusesEveryTruncatedFile) {
    const auto file = smallKtx2Cube();
    EXPECT_EQ(ktx2Error({}), "'bad.ktx2' is empty");
    EXPECT_EQ(ktx2Error(testing::prefix(file, 40)), "'bad.ktx2' is truncated: the header needs 48 bytes, the file has 40");
    EXPECT_EQ(ktx2Error(testing::prefix(file, 100)), "'bad.ktx2' is truncated: the level index needs 152 bytes, the file has 100");
    EXPECT_EQ(ktx2Error(testing::prefix(file, 1287)), "'bad.ktx2' is truncated: level 0 needs 1288 bytes, the file has 1287");
    for (size_t length = 0; length < file.size(); ++length)
        EXPECT_NE(ktx2Error(testing::prefix(file, length)).find("'bad.ktx2'"), std::string::npos) << "cut at " << length;
}

TEST(ImageIoKtx2Reader, RefusesFilesThatAreNotKtx2) {
    EXPECT_EQ(ktx2Error(testing::bytesOf("\xABKTX 11\xBB\r\n\x1A\n and the rest of a KTX 1 file")),
              "'bad.ktx2' is not a KTX 2.0 file (its first 12 bytes are not the KTX 2.0 identifier)");
    EXPECT_NE(ktx2Error(poked<uint8_t>(smallKtx2Cube(), 8, 0x0A)).find("not a KTX 2.0 file"), std::string::npos) << "CR-LF translated";
}

TEST(ImageIoKtx2Reader, NamesUnsupportedFormats) {
    EXPECT_EQ(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 12, 122)),
              "'bad.ktx2' has vkFormat 122 (B10G11R11_UFLOAT_PACK32); supported: 97 (R16G16B16A16_SFLOAT), "
              "109 (R32G32B32A32_SFLOAT), 83 (R16G16_SFLOAT), 103 (R32G32_SFLOAT)");
    EXPECT_NE(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 12, 0)).find("vkFormat 0 (UNDEFINED, e.g. Basis Universal)"), std::string::npos);
    EXPECT_NE(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 12, 1000)).find("vkFormat 1000;"), std::string::npos);
    EXPECT_EQ(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 16, 4)), "'bad.ktx2' has typeSize 4; R16G16B16A16_SFLOAT needs 2");
}

TEST(ImageIoKtx2Reader, RefusesSupercompressedFiles) {
    EXPECT_EQ(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 44, 2)),
              "'bad.ktx2' is supercompressed with scheme 2 (Zstandard); only files without supercompression (scheme 0) are supported");
    EXPECT_NE(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 44, 1)).find("scheme 1 (BasisLZ)"), std::string::npos);
}

TEST(ImageIoKtx2Reader, RefusesArrays3DAnd1DTextures) {
    EXPECT_EQ(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 32, 6)), "'bad.ktx2' is an array texture (layerCount 6); arrays are not supported");
    EXPECT_NE(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 28, 4)).find("is a 3D texture (pixelDepth 4)"), std::string::npos);
    EXPECT_NE(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 24, 0)).find("is a 1D texture"), std::string::npos);
}

TEST(ImageIoKtx2Reader, RefusesShapesItCannotHold) {
    EXPECT_EQ(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 36, 2)), "'bad.ktx2' has 2 faces; supported: 1, or 6 for a cube");
    EXPECT_NE(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 24, 2)).find("is a cube with faces that are not square (4x2)"), std::string::npos);
    EXPECT_EQ(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 40, 4)), "'bad.ktx2' has 4 mips; a 4x4 texture has at most 3");
    EXPECT_NE(ktx2Error(poked<uint32_t>(poked<uint32_t>(smallKtx2Cube(), 20, 0xFFFFFFFF), 24, 0xFFFFFFFF)).find("larger than 65536"),
              std::string::npos);
    EXPECT_NE(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 20, 0)).find("width or height of 0"), std::string::npos);
}

TEST(ImageIoKtx2Reader, RefusesACorruptIndex) {
    EXPECT_NE(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 48, 5000)).find("truncated: the Data Format Descriptor needs 5092 bytes"), std::string::npos);
    EXPECT_NE(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 48, 0)).find("corrupt index: the Data Format Descriptor (92 bytes at 0) overlaps"), std::string::npos);
    EXPECT_NE(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 52, 96)).find("dfdTotalSize differs from dfdByteLength"), std::string::npos);
    EXPECT_NE(ktx2Error(poked<uint32_t>(smallKtx2Cube(), 60, 5000)).find("truncated: the key/value data needs 5244 bytes"), std::string::npos);
    EXPECT_NE(ktx2Error(poked<uint64_t>(smallKtx2Cube(), 72, 8)).find("supercompression global data"), std::string::npos);
}

TEST(ImageIoKtx2Reader, RefusesACorruptLevelIndex) {
    EXPECT_EQ(ktx2Error(poked<uint64_t>(smallKtx2Cube(), 88, 767)),
              "'bad.ktx2' has a corrupt level index: level 0 has byteLength 767 and uncompressedByteLength 768; its size needs 768");
    EXPECT_NE(ktx2Error(poked<uint64_t>(smallKtx2Cube(), 80 + 24 + 16, 0)).find("level 1 has byteLength 192 and uncompressedByteLength 0"),
              std::string::npos);
    EXPECT_NE(ktx2Error(poked<uint64_t>(smallKtx2Cube(), 80 + 48, 1u << 20)).find("truncated: level 2 needs"), std::string::npos);
    EXPECT_NE(ktx2Error(poked<uint64_t>(smallKtx2Cube(), 80, UINT64_MAX - 100)).find("needs more than 2^64 bytes"), std::string::npos);
    EXPECT_NE(ktx2Error(poked<uint64_t>(smallKtx2Cube(), 80, 0)).find("level 0 starts inside the header"), std::string::npos);
}

// Accepted before: the specification requires each of these, and a reader that takes them reads
// garbage or one level twice.
TEST(ImageIoKtx2Reader, RefusesWhatTheSpecificationForbidsInTheIndex) {
    const auto cube = smallKtx2Cube();
    const uint64_t level1 = peek64(cube, 80 + 24), level2 = peek64(cube, 80 + 48);
    EXPECT_NE(ktx2Error(poked<uint64_t>(cube, 80 + 24, level2)).find("levels 1 and 2 overlap"), std::string::npos);
    EXPECT_NE(ktx2Error(poked<uint64_t>(cube, 80 + 24, level1 + 4)).find("level 1 starts at " + std::to_string(level1 + 4) +
                                                                         ", not a multiple of 8"),
              std::string::npos);
    EXPECT_NE(ktx2Error(poked<uint64_t>(cube, 64, 200)).find("sgdByteOffset is 200 with no supercompression global data"),
              std::string::npos);
    EXPECT_NO_THROW(decodeKtx2(cube, "good.ktx2"));
}

} // namespace
} // namespace iblkit::image_io
