// readFloatImage choosing the reader by extension, and writePng.
#include "float_image.hpp"
#include "image_io_test_support.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>
#include <stb_image.h>
#include <stb_image_write.h>

namespace iblkit::image_io {
namespace {

using iblkit::testing::TempFolder;
using testing::imageErrorOf;

TEST(ImageIoFloatImage, ReadFloatImageChoosesTheReaderByExtension) {
    TempFolder scratch;
    const std::vector<float> rgb(8 * 2 * 3, 0.75f);
    for (const char* name : {"a.hdr", "b.HDR", "c.pic"}) {
        ASSERT_TRUE(stbi_write_hdr((scratch.path() / name).c_str(), 8, 2, 3, rgb.data()));
        EXPECT_EQ(readFloatImage(scratch.path() / name).channels, 3u) << name;
    }
    writeExr(scratch.path() / "d.Exr", FloatImage{8, 2, 3, rgb});
    EXPECT_EQ(readFloatImage(scratch.path() / "d.Exr").channels, 4u);
    // The extension decides, not the contents.
    std::filesystem::copy_file(scratch.path() / "a.hdr", scratch.path() / "e.exr");
    EXPECT_NE(imageErrorOf([&] { readFloatImage(scratch.path() / "e.exr"); }).find("is not a readable OpenEXR image"), std::string::npos);
}

TEST(ImageIoFloatImage, ReadFloatImageNamesTheSupportedExtensions) {
    EXPECT_EQ(imageErrorOf([] { readFloatImage("x.png"); }), "unsupported image format '.png' for 'x.png' (supported: .hdr, .exr)");
    EXPECT_EQ(imageErrorOf([] { readFloatImage("sky"); }), "unsupported image format (no extension) for 'sky' (supported: .hdr, .exr)");
}

TEST(ImageIoPng, WritesRgba8ThatReadsBackTheSame) {
    TempFolder scratch;
    std::vector<uint8_t> rgba;
    for (int i = 0; i < 5 * 3 * 4; ++i) rgba.push_back(uint8_t(i * 37));
    writePng(scratch.path() / "preview.png", 5, 3, rgba);
    int width = 0, height = 0, channels = 0;
    stbi_uc* read = stbi_load((scratch.path() / "preview.png").c_str(), &width, &height, &channels, 4);
    ASSERT_NE(read, nullptr);
    EXPECT_EQ(width, 5);
    EXPECT_EQ(height, 3);
    EXPECT_EQ(channels, 4);
    EXPECT_EQ(std::vector<uint8_t>(read, read + rgba.size()), rgba);
    stbi_image_free(read);
}

TEST(ImageIoPng, RefusesWhatItCannotWrite) {
    TempFolder scratch;
    const auto path = scratch.path() / "missing" / "preview.png";
    EXPECT_EQ(imageErrorOf([&] { writePng(path, 1, 1, std::vector<uint8_t>(4)); }),
              "cannot write '" + path.string() + "': No such file or directory");
    EXPECT_EQ(imageErrorOf([&] { writePng("p.png", 2, 2, std::vector<uint8_t>(15)); }),
              "cannot write 'p.png': 15 bytes given; 2x2 RGBA8 needs 16");
    EXPECT_EQ(imageErrorOf([&] { writePng("p.png", 0, 2, {}); }), "cannot write 'p.png': the image is 0x2");
}

} // namespace
} // namespace iblkit::image_io
