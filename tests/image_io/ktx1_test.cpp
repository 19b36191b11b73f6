// The KTX1 writer (Filament's container) against the validator written from the KTX 1.1
// specification, the texels where the specification puts them, and the validator able to fail:
// every rule it checks, broken on purpose, is reported by the field it is about.
#include "image_io_test_support.hpp"
#include "ktx1.hpp"
#include "ktx1_validator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace iblkit::testing {
namespace {

using image_io::PixelFormat;

// An 8x8 RGBA16F cube with 2 mips and one key/value pair.
image_io::Texture goodTexture() { return patternedTexture(PixelFormat::Rgba16Float, 8, 8, 6, 2); }
std::vector<std::byte> goodKtx1File() { return image_io::encodeKtx1(goodTexture(), {{"iblkit.profile", "filament"}}); }

TEST(ImageIoKtx1, EveryFormatAndShapeConforms) {
    for (auto format : {PixelFormat::Rgba16Float, PixelFormat::Rgba32Float, PixelFormat::Rg16Float, PixelFormat::Rg32Float}) {
        EXPECT_EQ(validateKtx1(image_io::encodeKtx1(patternedTexture(format, 16, 16, 6, 5))), std::vector<std::string>{});
        EXPECT_EQ(validateKtx1(image_io::encodeKtx1(patternedTexture(format, 8, 4, 1, 4))), std::vector<std::string>{});
    }
    EXPECT_EQ(validateKtx1(goodKtx1File()), std::vector<std::string>{});
}

TEST(ImageIoKtx1, EachLevelIsItsImageSizeThenItsFacesInOrder) {
    const auto texture = goodTexture();
    const auto file = goodKtx1File();
    const size_t keyValues = peek32(file, 60);
    size_t offset = 64 + keyValues;
    for (uint32_t mip = 0; mip < texture.mips; ++mip) {
        ASSERT_EQ(peek32(file, offset), texture.faceBytes(mip)) << "mip " << mip << ": one face's bytes";
        EXPECT_TRUE(std::equal(texture.levels[mip].begin(), texture.levels[mip].end(), file.begin() + std::ptrdiff_t(offset + 4)))
            << "mip " << mip;
        offset += 4 + texture.levels[mip].size();
    }
    EXPECT_EQ(offset, file.size());
    const std::string keys(reinterpret_cast<const char*>(file.data()) + 68, keyValues - 4);
    EXPECT_EQ(keys.substr(0, keys.find('\0')), "iblkit.profile");
}

TEST(ImageIoKtx1Validator, ReportsEachBrokenRuleByItsField) {
    const auto good = goodKtx1File();
    auto longer = good;
    longer.push_back(std::byte{0});
    const size_t firstLevel = 64 + peek32(good, 60);
    const std::vector<std::tuple<std::string, std::vector<std::byte>, std::string>> broken = {
        {"identifier", poked<uint8_t>(good, 1, 'k'), "identifier:"},
        {"endianness", poked<uint32_t>(good, 12, 0x01020304), "endianness:"},
        {"glType", poked<uint32_t>(good, 16, 0x1401), "glType:"},
        {"glTypeSize", poked<uint32_t>(good, 20, 4), "glTypeSize:"},
        {"glFormat", poked<uint32_t>(good, 24, 0x1907), "glFormat:"},
        {"glInternalFormat", poked<uint32_t>(good, 28, 0x8814), "glInternalFormat:"},
        {"glBaseInternalFormat", poked<uint32_t>(good, 32, 0x8227), "glBaseInternalFormat:"},
        {"non-square cube", poked<uint32_t>(good, 40, 4), "square"},
        {"depth", poked<uint32_t>(good, 44, 1), "pixelDepth:"},
        {"array", poked<uint32_t>(good, 48, 2), "numberOfArrayElements:"},
        {"faces", poked<uint32_t>(good, 52, 3), "numberOfFaces:"},
        {"too many mips", poked<uint32_t>(good, 56, 5), "numberOfMipmapLevels:"},
        {"key/value size", poked<uint32_t>(good, 60, peek32(good, 60) + 2), "bytesOfKeyValueData:"},
        {"pair size", poked<uint32_t>(good, 64, 400), "keyAndValueByteSize:"},
        {"imageSize of all six faces", poked<uint32_t>(good, firstLevel, peek32(good, firstLevel) * 6), "imageSize:"},
        {"truncated", prefix(good, good.size() - 1), "file size:"},
        {"trailing byte", longer, "file size:"},
    };
    for (const auto& [what, file, reported] : broken)
        EXPECT_TRUE(mentions(validateKtx1(file), reported))
            << what << ": expected a violation mentioning \"" << reported << "\", got " << ::testing::PrintToString(validateKtx1(file));
}

} // namespace
} // namespace iblkit::testing
