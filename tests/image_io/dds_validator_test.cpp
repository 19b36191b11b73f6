// The DDS validator must be able to fail: every rule it checks, broken on purpose in an
// otherwise conforming file, is reported by the field it is about.
#include "dds.hpp"
#include "dds_validator.hpp"
#include "image_io_test_support.hpp"

#include <gtest/gtest.h>

namespace iblkit::testing {
namespace {

using image_io::PixelFormat;

// An 8x8 RGBA16F cube with 2 mips: pitch 64, 148 + 6 x (512 + 128) bytes.
std::vector<std::byte> goodFile() { return image_io::encodeDds(patternedTexture(PixelFormat::Rgba16Float, 8, 8, 6, 2)); }

struct Broken {
    std::string what;
    std::vector<std::byte> file;
    std::string reported;
};

std::vector<Broken> brokenFiles() {
    const auto good = goodFile();
    auto longer = good;
    longer.push_back(std::byte{0});
    const uint32_t flags = peek32(good, 8), caps = peek32(good, 108);
    return {
        {"short file", prefix(good, 147), "file size:"},
        {"magic", poked<uint8_t>(good, 3, 'X'), "magic:"},
        {"dwSize", poked<uint32_t>(good, 4, 100), "dwSize:"},
        {"no DDSD_PIXELFORMAT", poked<uint32_t>(good, 8, flags & ~0x1000u), "dwFlags: must have DDSD_CAPS"},
        {"no DDSD_MIPMAPCOUNT", poked<uint32_t>(good, 8, flags & ~0x20000u), "DDSD_MIPMAPCOUNT"},
        {"DDSD_LINEARSIZE for DDSD_PITCH", poked<uint32_t>(good, 8, (flags & ~0x8u) | 0x80000), "DDSD_PITCH"},
        {"pitch", poked<uint32_t>(good, 20, 32), "dwPitchOrLinearSize:"},
        {"depth", poked<uint32_t>(good, 24, 1), "dwDepth:"},
        {"too many mips", poked<uint32_t>(good, 28, 5), "dwMipMapCount:"},
        {"DDS_PIXELFORMAT dwSize", poked<uint32_t>(good, 76, 24), "DDS_PIXELFORMAT dwSize:"},
        {"DDS_PIXELFORMAT dwFlags", poked<uint32_t>(good, 80, 0x41), "DDS_PIXELFORMAT dwFlags:"},
        {"FourCC", poked(good, 84, std::array<char, 4>{'D', 'X', 'T', '5'}), "dwFourCC:"},
        {"no DDSCAPS_TEXTURE", poked<uint32_t>(good, 108, caps & ~0x1000u), "DDSCAPS_TEXTURE"},
        {"no DDSCAPS_MIPMAP", poked<uint32_t>(good, 108, caps & ~0x400000u), "DDSCAPS_MIPMAP"},
        {"a face missing", poked<uint32_t>(good, 112, 0x200 | 0x7C00), "dwCaps2: a cube must have"},
        {"cube flags only in dwCaps2", poked<uint32_t>(good, 136, 0), "dwCaps2: must be 0 unless"},
        {"non-square cube", poked<uint32_t>(good, 12, 4), "square"},
        {"unknown DXGI format", poked<uint32_t>(good, 128, 28), "dxgiFormat:"},
        {"3D resource", poked<uint32_t>(good, 132, 4), "resourceDimension:"},
        {"another misc flag", poked<uint32_t>(good, 136, 0x4 | 0x2), "miscFlag:"},
        {"arraySize 6", poked<uint32_t>(good, 140, 6), "arraySize:"},
        {"arraySize 0", poked<uint32_t>(good, 140, 0), "arraySize:"},
        {"alpha mode", poked<uint32_t>(good, 144, 7), "miscFlags2:"},
        {"truncated", prefix(good, good.size() - 1), "file size:"},
        {"trailing byte", longer, "file size:"},
    };
}

TEST(ImageIoDdsValidator, FindsNothingWrongWithAConformingFile) { EXPECT_EQ(validateDds(goodFile()), std::vector<std::string>{}); }

TEST(ImageIoDdsValidator, ReportsEachBrokenRuleByItsField) {
    for (const auto& broken : brokenFiles()) {
        const auto violations = validateDds(broken.file);
        EXPECT_TRUE(mentions(violations, broken.reported))
            << broken.what << ": expected a violation mentioning \"" << broken.reported << "\", got "
            << ::testing::PrintToString(violations);
    }
}

} // namespace
} // namespace iblkit::testing
