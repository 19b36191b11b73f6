// OpenEXR: the writer's float files read back exactly, files from other tools (half, uint, tiled,
// data windows, every compression, luminance/chroma) read within their codec's error, and bad
// files refused with one line.
#include "files.hpp"
#include "float_image.hpp"
#include "image_io_test_support.hpp"
#include "temp_folder.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <ImfTiledOutputFile.h>
#include <gtest/gtest.h>

#include <cmath>

namespace iblkit::image_io {
namespace {

using iblkit::testing::TempFolder;
using testing::imageErrorOf;

// Values over sixty binary orders of magnitude, both signs, none representable as a half.
FloatImage wideRange(uint32_t width, uint32_t height, uint32_t channels) {
    FloatImage image{width, height, channels, {}};
    for (uint32_t k = 0; k < width * height * channels; ++k)
        image.values.push_back((k % 3 == 1 ? -1.f : 1.f) * std::ldexp(1.f + float(k % 97) / 97.f + 1e-6f, int(k % 60) - 30));
    return image;
}

void writeHalfRgba(const std::filesystem::path& path, int width, int height, const std::vector<Imf::Rgba>& pixels,
                   Imf::Compression compression) {
    Imf::Header header(width, height);
    header.compression() = compression;
    Imf::RgbaOutputFile file(path.c_str(), header, Imf::WRITE_RGBA);
    file.setFrameBuffer(pixels.data(), 1, size_t(width));
    file.writePixels(height);
}

// Writes float channels named `names` from `values` (interleaved) over `window`.
void writeFloatChannels(const std::filesystem::path& path, const Imath::Box2i& window, const std::vector<std::string>& names,
                        std::vector<float>& values) {
    Imf::Header header(Imath::Box2i({0, 0}, {99, 99}), window);
    Imf::FrameBuffer frame;
    const size_t xStride = names.size() * sizeof(float), yStride = xStride * size_t(window.max.x - window.min.x + 1);
    for (size_t c = 0; c < names.size(); ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
        frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, values.data() + c, window, xStride, yStride));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(window.max.y - window.min.y + 1);
}

TEST(ImageIoExr, WriteThenReadIsExactForFloats) {
    TempFolder scratch;
    for (uint32_t channels : {3u, 4u}) {
        const auto image = wideRange(13, 7, channels);
        const auto path = scratch.path() / ("float" + std::to_string(channels) + ".exr");
        writeExr(path, image);
        const auto read = readExr(path);
        ASSERT_EQ(read.width, 13u);
        ASSERT_EQ(read.height, 7u);
        ASSERT_EQ(read.channels, 4u);
        for (size_t texel = 0; texel < 13 * 7; ++texel)
            for (uint32_t c = 0; c < 4; ++c)
                EXPECT_EQ(read.values[texel * 4 + c], c < channels ? image.values[texel * channels + c] : 1.f)
                    << "texel " << texel << " channel " << c;
    }
}

TEST(ImageIoExr, WritesFloatChannelsWithZipCompression) {
    TempFolder scratch;
    writeExr(scratch.path() / "a.exr", wideRange(4, 3, 3));
    Imf::InputFile file((scratch.path() / "a.exr").c_str());
    EXPECT_EQ(file.header().compression(), Imf::ZIP_COMPRESSION);
    std::vector<std::string> names;
    for (auto channel = file.header().channels().begin(); channel != file.header().channels().end(); ++channel) {
        names.push_back(channel.name());
        EXPECT_EQ(channel.channel().type, Imf::FLOAT) << channel.name();
    }
    EXPECT_EQ(names, (std::vector<std::string>{"B", "G", "R"})); // OpenEXR lists channels by name
    EXPECT_EQ(file.header().dataWindow(), Imath::Box2i({0, 0}, {3, 2}));
}

// Half RGBA files as cameras and tools write them. Lossless codecs (PXR24 too, for halves) give
// the halves back exactly, so the reader adds nothing; the bounds of the lossy ones are their own
// error on this noisy ramp, measured with a margin: B44 stores 4x4 blocks as 6-bit differences
// (measured 0.16 relative), DWA is a DCT codec at its default quality 45 (measured 0.025).
TEST(ImageIoExr, ReadsHalfFilesOfEveryCompression) {
    TempFolder scratch;
    const int width = 64, height = 32;
    std::vector<Imf::Rgba> pixels;
    for (int i = 0; i < width * height; ++i) {
        const float noise = float((i * 2654435761u) >> 24) / 256.f; // texture for the lossy codecs to lose
        pixels.emplace_back(float(i % width) / 8 + noise, float(i / width) / 4 + 1, 2.f - noise, 0.5f);
    }
    const std::pair<Imf::Compression, double> codecs[] = {
        {Imf::NO_COMPRESSION, 0},  {Imf::RLE_COMPRESSION, 0},   {Imf::ZIPS_COMPRESSION, 0},  {Imf::ZIP_COMPRESSION, 0},
        {Imf::PIZ_COMPRESSION, 0}, {Imf::PXR24_COMPRESSION, 0}, {Imf::B44_COMPRESSION, 0.25}, {Imf::B44A_COMPRESSION, 0.25},
        {Imf::DWAA_COMPRESSION, 0.05}, {Imf::DWAB_COMPRESSION, 0.05}};
    for (const auto& [compression, bound] : codecs) {
        const auto path = scratch.path() / ("c" + std::to_string(int(compression)) + ".exr");
        writeHalfRgba(path, width, height, pixels, compression);
        const auto read = readExr(path);
        ASSERT_EQ(read.values.size(), size_t(width * height * 4));
        double worst = 0;
        for (int i = 0; i < width * height; ++i) {
            const float expected[4] = {pixels[i].r, pixels[i].g, pixels[i].b, pixels[i].a};
            for (int c = 0; c < 4; ++c)
                worst = std::max(worst, std::abs(double(read.values[4 * i + c]) - expected[c]) / std::max(1.f, std::abs(expected[c])));
        }
        EXPECT_LE(worst, bound) << "compression " << int(compression);
    }
}

TEST(ImageIoExr, HonoursTheDataWindow) {
    TempFolder scratch;
    const Imath::Box2i window({10, 20}, {14, 22}); // 5x3, away from the origin
    auto values = wideRange(5, 3, 3).values;
    writeFloatChannels(scratch.path() / "window.exr", window, {"R", "G", "B"}, values);
    const auto read = readExr(scratch.path() / "window.exr");
    ASSERT_EQ(read.width, 5u);
    ASSERT_EQ(read.height, 3u);
    for (size_t texel = 0; texel < 15; ++texel)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(read.values[texel * 4 + c], values[texel * 3 + c]) << texel;
}

TEST(ImageIoExr, ConvertsHalfAndUintChannelsToFloat) {
    TempFolder scratch;
    const auto path = scratch.path() / "mixed.exr";
    std::vector<uint32_t> red = {0, 7, 1u << 20, 4000000000u};
    std::vector<Imath::half> green = {Imath::half(0.5f), Imath::half(-2.f), Imath::half(65504.f), Imath::half(1e-3f)};
    std::vector<float> blue = {0.1f, 1e20f, -3.f, 7.f};
    {
        Imf::Header header(4, 1);
        header.channels().insert("R", Imf::Channel(Imf::UINT));
        header.channels().insert("G", Imf::Channel(Imf::HALF));
        header.channels().insert("B", Imf::Channel(Imf::FLOAT));
        Imf::FrameBuffer frame;
        frame.insert("R", Imf::Slice(Imf::UINT, reinterpret_cast<char*>(red.data()), 4, 16));
        frame.insert("G", Imf::Slice(Imf::HALF, reinterpret_cast<char*>(green.data()), 2, 8));
        frame.insert("B", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(blue.data()), 4, 16));
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(1);
    }
    const auto read = readExr(path);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(read.values[4 * i], float(red[i])) << i;
        EXPECT_EQ(read.values[4 * i + 1], float(green[i])) << i;
        EXPECT_EQ(read.values[4 * i + 2], blue[i]) << i;
        EXPECT_EQ(read.values[4 * i + 3], 1.f) << i;
    }
}

TEST(ImageIoExr, ReadsTiledFiles) {
    TempFolder scratch;
    const auto path = scratch.path() / "tiled.exr";
    auto image = wideRange(37, 21, 4);
    {
        Imf::Header header(37, 21);
        header.setTileDescription(Imf::TileDescription(16, 16, Imf::ONE_LEVEL));
        Imf::FrameBuffer frame;
        const char* names[] = {"R", "G", "B", "A"};
        for (int c = 0; c < 4; ++c) {
            header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
            frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(image.values.data() + c), 16, 16 * 37));
        }
        Imf::TiledOutputFile file(path.c_str(), header);
        file.setFrameBuffer(frame);
        file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
    }
    EXPECT_EQ(readExr(path).values, image.values);
}

// Y/RY/BY files store luminance, and chroma as (R - Y) / Y and (B - Y) / Y at half resolution,
// all as halves: a flat colour comes back within a few half ulps (2^-11) compounded by the
// conversion (measured 4.9e-3 relative).
TEST(ImageIoExr, ReadsLuminanceChromaAndLuminanceFiles) {
    TempFolder scratch;
    const std::vector<Imf::Rgba> flat(16 * 8, Imf::Rgba(0.5f, 0.25f, 0.125f, 1.f));
    {
        Imf::RgbaOutputFile file((scratch.path() / "yc.exr").c_str(), Imf::Header(16, 8), Imf::WRITE_YCA);
        file.setFrameBuffer(flat.data(), 1, 16);
        file.writePixels(8);
    }
    const auto yc = readExr(scratch.path() / "yc.exr");
    for (size_t i = 0; i < 16 * 8; ++i) {
        EXPECT_NEAR(yc.values[4 * i], 0.5f, 0.5f * 1e-2) << i;
        EXPECT_NEAR(yc.values[4 * i + 1], 0.25f, 0.25f * 1e-2) << i;
        EXPECT_NEAR(yc.values[4 * i + 2], 0.125f, 0.125f * 1e-2) << i;
    }
    std::vector<Imf::Rgba> gray;
    for (int i = 0; i < 16 * 8; ++i) gray.emplace_back(float(i) / 4, float(i) / 4, float(i) / 4, 1.f);
    {
        Imf::RgbaOutputFile file((scratch.path() / "y.exr").c_str(), Imf::Header(16, 8), Imf::WRITE_Y);
        file.setFrameBuffer(gray.data(), 1, 16);
        file.writePixels(8);
    }
    const auto y = readExr(scratch.path() / "y.exr");
    for (size_t i = 0; i < 16 * 8; ++i)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(y.values[4 * i + c], float(i) / 4, float(i) / 4 * 1e-3) << i;
}

TEST(ImageIoExr, RefusesFilesWithoutColourChannels) {
    TempFolder scratch;
    std::vector<float> depth(4 * 2, 1.f);
    writeFloatChannels(scratch.path() / "z.exr", Imath::Box2i({0, 0}, {3, 1}), {"Z"}, depth);
    EXPECT_EQ(imageErrorOf([&] { readExr(scratch.path() / "z.exr"); }),
              "'" + (scratch.path() / "z.exr").string() +
                  "' has the channels Z; readable: R, G, B (and A), or Y (and RY, BY); layers are not supported");
    std::vector<float> layered(4 * 2 * 3, 1.f);
    writeFloatChannels(scratch.path() / "layer.exr", Imath::Box2i({0, 0}, {3, 1}), {"diffuse.R", "diffuse.G", "diffuse.B"}, layered);
    EXPECT_NE(imageErrorOf([&] { readExr(scratch.path() / "layer.exr"); }).find("has the channels diffuse.B, diffuse.G, diffuse.R;"),
              std::string::npos);
}

TEST(ImageIoExr, RefusesMissingEmptyAndForeignFiles) {
    TempFolder scratch;
    const auto missing = scratch.path() / "missing.exr";
    EXPECT_EQ(imageErrorOf([&] { readExr(missing); }), "cannot open '" + missing.string() + "': No such file or directory");
    const auto empty = testing::writeBytes(scratch.path() / "empty.exr", {});
    EXPECT_NE(imageErrorOf([&] { readExr(empty); }).find("' is not a readable OpenEXR image: "), std::string::npos);
    const auto junk = testing::writeBytes(scratch.path() / "junk.exr", testing::bytesOf(std::string("\x76\x2f\x31\x01\x02\0\0\0junk", 12)));
    EXPECT_NE(imageErrorOf([&] { readExr(junk); }).find("is not a readable OpenEXR image"), std::string::npos);
    const auto hdr = testing::writeBytes(scratch.path() / "sky.exr", testing::bytesOf("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n"));
    EXPECT_NE(imageErrorOf([&] { readExr(hdr); }).find("is not a readable OpenEXR image"), std::string::npos);
}

// Cut anywhere in the header, the offset table or the pixel data: always one line, never a crash.
TEST(ImageIoExr, RefusesEveryTruncatedFile) {
    TempFolder scratch;
    for (const auto compression : {Imf::ZIP_COMPRESSION, Imf::PIZ_COMPRESSION, Imf::NO_COMPRESSION}) {
        const auto whole = scratch.path() / "whole.exr";
        std::vector<Imf::Rgba> pixels(16 * 8, Imf::Rgba(1.f, 2.f, 3.f, 1.f));
        writeHalfRgba(whole, 16, 8, pixels, compression);
        const auto bytes = readFileBytes(whole);
        for (size_t length = 0; length < bytes.size(); length += length < 400 ? 1 : 7) {
            const auto cut = testing::writeBytes(scratch.path() / "cut.exr", testing::prefix(bytes, length));
            EXPECT_NE(imageErrorOf([&] { readExr(cut); }).find("cut.exr"), std::string::npos)
                << "compression " << int(compression) << " cut at " << length << " of " << bytes.size();
        }
    }
}

TEST(ImageIoExr, WriterRefusesImagesItCannotWrite) {
    TempFolder scratch;
    const auto path = scratch.path() / "no" / "such" / "folder.exr";
    EXPECT_NE(imageErrorOf([&] { writeExr(path, wideRange(2, 2, 3)); }).find("cannot write '" + path.string() + "': "),
              std::string::npos);
    EXPECT_NE(imageErrorOf([&] { writeExr(scratch.path() / "a.exr", wideRange(2, 2, 2)); }).find("EXR output needs 3 or 4"),
              std::string::npos);
    auto shortImage = wideRange(2, 2, 3);
    shortImage.values.pop_back();
    EXPECT_NE(imageErrorOf([&] { writeExr(scratch.path() / "a.exr", shortImage); }).find("holds 11 values; 2x2x3 needs 12"),
              std::string::npos);
}

} // namespace
} // namespace iblkit::image_io
