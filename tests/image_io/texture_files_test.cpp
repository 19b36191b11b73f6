// KTX2 and DDS files of every format and shape: exact round trips through the kit's own writer
// and reader, files the independent validators find conforming, and readTextureFile choosing
// the reader by extension.
#include "dds.hpp"
#include "dds_validator.hpp"
#include "files.hpp"
#include "image_io_test_support.hpp"
#include "ktx2.hpp"
#include "ktx2_validator.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

namespace iblkit::image_io {
namespace {

using testing::imageErrorOf;
using testing::patternedTexture;

struct Shape {
    PixelFormat format;
    uint32_t width, height, faces, mips;
};

std::string formatName(PixelFormat format) {
    switch (format) {
    case PixelFormat::Rgba16Float: return "Rgba16Float";
    case PixelFormat::Rgba32Float: return "Rgba32Float";
    case PixelFormat::Rg16Float: return "Rg16Float";
    case PixelFormat::Rg32Float: return "Rg32Float";
    }
    return "?";
}

std::vector<Shape> everyFormatAndShape() {
    std::vector<Shape> shapes;
    for (auto format : {PixelFormat::Rgba16Float, PixelFormat::Rgba32Float, PixelFormat::Rg16Float, PixelFormat::Rg32Float})
        for (const Shape& shape : {Shape{format, 1, 1, 1, 1}, Shape{format, 5, 3, 1, 1}, Shape{format, 5, 3, 1, 3},
                                   Shape{format, 32, 8, 1, 6}, Shape{format, 8, 8, 6, 1}, Shape{format, 16, 16, 6, 5}})
            shapes.push_back(shape);
    return shapes;
}

void PrintTo(const Shape& s, std::ostream* out) {
    *out << formatName(s.format) << " " << s.width << "x" << s.height << " faces " << s.faces << " mips " << s.mips;
}

std::string shapeName(const ::testing::TestParamInfo<Shape>& info) {
    const Shape& s = info.param;
    return formatName(s.format) + (s.faces == 6 ? "_cube" : "_") + std::to_string(s.width) + "x" + std::to_string(s.height) +
           "_" + std::to_string(s.mips) + "mips";
}

class ImageIoTextureFiles : public ::testing::TestWithParam<Shape> {
protected:
    Texture texture() const {
        const Shape& s = GetParam();
        return patternedTexture(s.format, s.width, s.height, s.faces, s.mips);
    }
    // Writer names of different lengths move the end of the key/value data, and with it the
    // padding before the first level.
    std::string writer() const { return "iblkit test" + std::string(GetParam().width % 4, '+'); }
};

void expectSameTexture(const Texture& read, const Texture& written) {
    EXPECT_EQ(read.format, written.format);
    EXPECT_EQ(read.width, written.width);
    EXPECT_EQ(read.height, written.height);
    EXPECT_EQ(read.faces, written.faces);
    EXPECT_EQ(read.mips, written.mips);
    EXPECT_TRUE(read.levels == written.levels) << "the texels differ";
}

TEST_P(ImageIoTextureFiles, Ktx2ReadsBackTheSameTexture) {
    expectSameTexture(decodeKtx2(encodeKtx2(texture(), writer()), "t.ktx2"), texture());
}

TEST_P(ImageIoTextureFiles, Ktx2FilesPassTheIndependentValidator) {
    EXPECT_EQ(testing::validateKtx2(encodeKtx2(texture(), writer())), std::vector<std::string>{});
}

TEST_P(ImageIoTextureFiles, DdsReadsBackTheSameTexture) {
    expectSameTexture(decodeDds(encodeDds(texture()), "t.dds"), texture());
}

TEST_P(ImageIoTextureFiles, DdsFilesPassTheIndependentValidator) {
    EXPECT_EQ(testing::validateDds(encodeDds(texture())), std::vector<std::string>{});
}

INSTANTIATE_TEST_SUITE_P(EveryFormatAndShape, ImageIoTextureFiles, ::testing::ValuesIn(everyFormatAndShape()), shapeName);

TEST(ImageIoTextureWriters, RefuseTexturesWhoseLevelsDoNotMatchTheirShape) {
    auto texture = patternedTexture(PixelFormat::Rgba16Float, 4, 4, 1, 2);
    texture.levels[1].pop_back();
    EXPECT_NE(imageErrorOf([&] { encodeKtx2(texture, "w"); }).find("encodeKtx2: mip 1 holds 31 bytes; its size needs 32"),
              std::string::npos);
    EXPECT_NE(imageErrorOf([&] { encodeDds(texture); }).find("encodeDds: mip 1"), std::string::npos);
    texture.mips = 3;
    EXPECT_NE(imageErrorOf([&] { encodeKtx2(texture, "w"); }).find("2 levels for 3 mips"), std::string::npos);
}

TEST(ImageIoFiles, ReadTextureFileChoosesTheReaderByExtension) {
    iblkit::testing::TempFolder scratch;
    const auto texture = patternedTexture(PixelFormat::Rg16Float, 4, 2, 1, 2);
    testing::writeBytes(scratch.path() / "lut.KTX2", encodeKtx2(texture, "w"));
    testing::writeBytes(scratch.path() / "lut.Dds", encodeDds(texture));
    EXPECT_TRUE(readTextureFile(scratch.path() / "lut.KTX2").levels == texture.levels);
    EXPECT_TRUE(readTextureFile(scratch.path() / "lut.Dds").levels == texture.levels);
    testing::writeBytes(scratch.path() / "swapped.dds", encodeKtx2(texture, "w"));
    EXPECT_NE(imageErrorOf([&] { readTextureFile(scratch.path() / "swapped.dds"); }).find("is not a DDS file"), std::string::npos);
}

TEST(ImageIoFiles, ReadTextureFileNamesTheSupportedExtensions) {
    EXPECT_EQ(imageErrorOf([] { readTextureFile("env/sky.png"); }),
              "unsupported texture format '.png' for 'env/sky.png' (supported: .ktx2, .dds)");
    EXPECT_EQ(imageErrorOf([] { readTextureFile("sky"); }),
              "unsupported texture format (no extension) for 'sky' (supported: .ktx2, .dds)");
}

TEST(ImageIoFiles, ReadFileBytesReadsEveryByteOrSaysWhyNot) {
    iblkit::testing::TempFolder scratch;
    const auto bytes = testing::bytesOf(std::string("a\0b\xff", 4));
    EXPECT_EQ(readFileBytes(testing::writeBytes(scratch.path() / "x.bin", bytes)), bytes);
    EXPECT_TRUE(readFileBytes(testing::writeBytes(scratch.path() / "empty.bin", {})).empty());
    const auto missing = (scratch.path() / "missing.ktx2").string();
    EXPECT_EQ(imageErrorOf([&] { readFileBytes(missing); }), "cannot open '" + missing + "': No such file or directory");
    EXPECT_EQ(imageErrorOf([&] { readTextureFile(missing); }), "cannot open '" + missing + "': No such file or directory");
    EXPECT_EQ(imageErrorOf([&] { readFileBytes(scratch.path()); }), "cannot open '" + scratch.path().string() + "': Is a directory");
}

} // namespace
} // namespace iblkit::image_io
