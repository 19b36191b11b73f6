// Radiance HDR through stb_image: RGBE decoded exactly, stb_image_write's files read within
// RGBE precision, and files that are not Radiance, or are truncated, refused.
#include "files.hpp"
#include "float_image.hpp"
#include "image_io_test_support.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>

namespace iblkit::image_io {
namespace {

using iblkit::testing::TempFolder;
using testing::imageErrorOf;

// Each texel is a shared exponent e and three 8-bit mantissas m: m * 2^(e - 136).
TEST(ImageIoRadianceHdr, DecodesRgbeExactlyRowsTopFirst) {
    TempFolder scratch;
    const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 3\n";
    const unsigned char texels[6][4] = {{128, 64, 32, 129}, {255, 0, 1, 140}, {0, 0, 0, 0},
                                        {1, 2, 3, 100},     {200, 100, 50, 128}, {17, 255, 34, 136}};
    const auto path = scratch.write("flat.hdr", header + std::string(reinterpret_cast<const char*>(texels), sizeof texels));
    const auto image = readRadianceHdr(path);
    ASSERT_EQ(image.width, 3u);
    ASSERT_EQ(image.height, 2u);
    ASSERT_EQ(image.channels, 3u);
    for (int t = 0; t < 6; ++t)
        for (int c = 0; c < 3; ++c) {
            const float expected = texels[t][3] == 0 ? 0.f : std::ldexp(float(texels[t][c]), texels[t][3] - 136);
            EXPECT_EQ(image.values[3 * t + c], expected) << "texel " << t << " channel " << c;
        }
}

// stb_image_write stores each channel as trunc(v * 256 / 2^e) with 2^(e-1) <= max channel < 2^e,
// so every channel loses less than 2^(e-8): less than 2^-7 of the texel's largest channel
// (2^-8 of 2^e), which also bounds the largest channel's own relative error. The reader adds
// nothing: it decodes m * 2^(e-8) exactly (see DecodesRgbeExactly).
TEST(ImageIoRadianceHdr, ReadsStbWrittenFilesWithinRgbePrecision) {
    TempFolder scratch;
    const int width = 40, height = 20; // wide enough for stb's run-length encoded scanlines
    std::vector<float> values;
    for (int i = 0; i < width * height * 3; ++i) values.push_back(std::ldexp(1.f + float(i % 89) / 89.f, i % 23 - 8));
    const auto path = scratch.path() / "sky.hdr";
    ASSERT_TRUE(stbi_write_hdr(path.c_str(), width, height, 3, values.data()));
    const auto image = readFloatImage(path);
    ASSERT_EQ(image.values.size(), values.size());
    for (int t = 0; t < width * height; ++t) {
        const float largest = std::max({values[3 * t], values[3 * t + 1], values[3 * t + 2]});
        for (int c = 0; c < 3; ++c)
            EXPECT_LT(std::abs(image.values[3 * t + c] - values[3 * t + c]), std::ldexp(largest, -7)) << "texel " << t;
    }
}

TEST(ImageIoRadianceHdr, RefusesFilesThatAreNotRadiance) {
    TempFolder scratch;
    const std::vector<uint8_t> rgba(4 * 4 * 4, 200);
    const auto png = scratch.path() / "ldr.hdr"; // an 8-bit PNG that stb would convert with a gamma
    writePng(png, 4, 4, rgba);
    EXPECT_EQ(imageErrorOf([&] { readRadianceHdr(png); }),
              "'" + png.string() + "' is not a Radiance HDR image: its first line is not #?RADIANCE or #?RGBE");
    const auto pfm = scratch.write("pfm.hdr", "PF\n1 1\n-1.0\n\0\0\x80\x3f\0\0\x80\x3f\0\0\x80\x3f");
    EXPECT_NE(imageErrorOf([&] { readRadianceHdr(pfm); }).find("is not a Radiance HDR image"), std::string::npos);
    const auto empty = scratch.write("empty.hdr", "");
    EXPECT_NE(imageErrorOf([&] { readRadianceHdr(empty); }).find("is not a Radiance HDR image"), std::string::npos);
    const auto missing = scratch.path() / "missing.hdr";
    EXPECT_EQ(imageErrorOf([&] { readFloatImage(missing); }), "cannot open '" + missing.string() + "': No such file or directory");
    const auto sideways = scratch.write("sideways.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+X 2 -Y 1\n\x80\x80\x80\x81\x80\x80\x80\x81");
    EXPECT_NE(imageErrorOf([&] { readRadianceHdr(sideways); }).find("has the resolution line '+X 2 -Y 1'; supported: -Y <height> +X <width>"),
              std::string::npos);
    const auto xyze = scratch.write("xyze.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n\x80\x80\x80\x81");
    EXPECT_NE(imageErrorOf([&] { readRadianceHdr(xyze); }).find("has no FORMAT=32-bit_rle_rgbe line"), std::string::npos);
}

// stb_image fills what is missing with black, or loops forever in a run-length encoded scanline;
// the reader must notice first.
TEST(ImageIoRadianceHdr, RefusesTruncatedFiles) {
    TempFolder scratch;
    std::vector<float> values(40 * 20 * 3, 1.5f);
    ASSERT_TRUE(stbi_write_hdr((scratch.path() / "whole.hdr").c_str(), 40, 20, 3, values.data()));
    const auto bytes = readFileBytes(scratch.path() / "whole.hdr");
    const std::string text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const size_t dataStart = text.find("+X 40\n") + 6;
    ASSERT_NE(dataStart, std::string::npos + 6);
    for (size_t length : {size_t(5), text.find("FORMAT"), dataStart - 7, dataStart, dataStart + 3, dataStart + 40,
                          (dataStart + bytes.size()) / 2, bytes.size() - 1}) {
        const auto cut = testing::writeBytes(scratch.path() / "cut.hdr", testing::prefix(bytes, length));
        EXPECT_NE(imageErrorOf([&] { readRadianceHdr(cut); }).find("cut.hdr'"), std::string::npos) << "cut at " << length;
    }
    EXPECT_NE(imageErrorOf([&] { readRadianceHdr(testing::writeBytes(scratch.path() / "cut.hdr", testing::prefix(bytes, bytes.size() - 1))); })
                  .find("' is truncated: its 40x20 pixels need more than the file's"),
              std::string::npos);
    const std::string flat = "#?RGBE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 3\n" + std::string(23, '\x80');
    EXPECT_NE(imageErrorOf([&] { readRadianceHdr(scratch.write("flat.hdr", flat)); }).find("is truncated: its 3x2 pixels"),
              std::string::npos);
}

TEST(ImageIoRadianceHdr, RefusesCorruptRunLengths) {
    TempFolder scratch;
    std::vector<float> values(40 * 2 * 3, 1.5f);
    ASSERT_TRUE(stbi_write_hdr((scratch.path() / "whole.hdr").c_str(), 40, 2, 3, values.data()));
    auto bytes = readFileBytes(scratch.path() / "whole.hdr");
    const std::string text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const size_t firstCount = text.find("+X 40\n") + 6 + 4; // after the scanline's 2, 2, 0, 40
    bytes[firstCount] = std::byte{0};                        // a zero run length: stb_image would never finish
    const auto zero = testing::writeBytes(scratch.path() / "zero.hdr", bytes);
    EXPECT_NE(imageErrorOf([&] { readRadianceHdr(zero); }).find("has a corrupt run-length encoded scanline (row 0)"), std::string::npos);
    bytes[firstCount] = std::byte{128 + 41}; // a run past the end of the scanline
    const auto overflow = testing::writeBytes(scratch.path() / "overflow.hdr", bytes);
    EXPECT_NE(imageErrorOf([&] { readRadianceHdr(overflow); }).find("corrupt run-length"), std::string::npos);
}

} // namespace
} // namespace iblkit::image_io
