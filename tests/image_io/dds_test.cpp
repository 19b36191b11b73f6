// The DDS writer checked field by field against Microsoft's DDS_HEADER and DDS_HEADER_DXT10
// documentation, legacy FourCC files read, and every kind of bad file refused with one line.
#include "dds.hpp"
#include "image_io_test_support.hpp"

#include <gtest/gtest.h>

namespace iblkit::image_io {
namespace {

using testing::imageErrorOf;
using testing::patternedTexture;
using testing::peek32;
using testing::poked;

// A 4x4 RGBA16F cube with 3 mips: 148 bytes of headers, then 6 faces of 128 + 32 + 8 bytes.
Texture smallCubeTexture() { return patternedTexture(PixelFormat::Rgba16Float, 4, 4, 6, 3); }
std::vector<std::byte> smallCube() { return encodeDds(smallCubeTexture()); }

std::string ddsError(const std::vector<std::byte>& bytes) {
    return imageErrorOf([&] { decodeDds(bytes, "bad.dds"); });
}

// The same file as Direct3D 9 tools wrote it: no DX10 header, the format in the FourCC.
std::vector<std::byte> legacy(const std::vector<std::byte>& dx10File, uint32_t fourCc) {
    auto file = testing::prefix(dx10File, 128);
    file.insert(file.end(), dx10File.begin() + 148, dx10File.end());
    return poked(file, 84, fourCc);
}

TEST(ImageIoDds, HeadersOfASmallCube) {
    const auto file = smallCube();
    EXPECT_EQ(std::memcmp(file.data(), "DDS ", 4), 0);
    EXPECT_EQ(peek32(file, 4), 124u);
    EXPECT_EQ(peek32(file, 8), 0x1u | 0x2 | 0x4 | 0x8 | 0x1000 | 0x20000) << "CAPS, HEIGHT, WIDTH, PITCH, PIXELFORMAT, MIPMAPCOUNT";
    EXPECT_EQ(peek32(file, 12), 4u);
    EXPECT_EQ(peek32(file, 16), 4u);
    EXPECT_EQ(peek32(file, 20), 32u) << "pitch: 4 texels of 8 bytes";
    EXPECT_EQ(peek32(file, 24), 0u);
    EXPECT_EQ(peek32(file, 28), 3u);
    EXPECT_EQ(peek32(file, 76), 32u);
    EXPECT_EQ(peek32(file, 80), 0x4u) << "DDPF_FOURCC";
    EXPECT_EQ(std::memcmp(file.data() + 84, "DX10", 4), 0);
    EXPECT_EQ(peek32(file, 108), 0x1000u | 0x8 | 0x400000) << "TEXTURE, COMPLEX, MIPMAP";
    EXPECT_EQ(peek32(file, 112), 0x200u | 0xFC00) << "CUBEMAP and all six faces";
    const uint32_t dx10[5] = {10, 3, 0x4, 1, 0}; // R16G16B16A16_FLOAT, TEXTURE2D, TEXTURECUBE, one cube, alpha unknown
    for (int i = 0; i < 5; ++i) EXPECT_EQ(peek32(file, 128 + 4 * i), dx10[i]) << "DDS_HEADER_DXT10 field " << i;
    EXPECT_EQ(file.size(), 148u + 6 * (128 + 32 + 8));
}

TEST(ImageIoDds, HeadersOfA2DTextureWithoutMips) {
    const auto file = encodeDds(patternedTexture(PixelFormat::Rg32Float, 5, 3, 1, 1));
    EXPECT_EQ(peek32(file, 20), 40u) << "pitch: 5 texels of 8 bytes";
    EXPECT_EQ(peek32(file, 28), 1u);
    EXPECT_EQ(peek32(file, 108), 0x1000u) << "a single surface is not COMPLEX";
    EXPECT_EQ(peek32(file, 112), 0u);
    EXPECT_EQ(peek32(file, 128), 16u) << "DXGI_FORMAT_R32G32_FLOAT";
    EXPECT_EQ(peek32(file, 136), 0u);
    EXPECT_EQ(file.size(), 148u + 5 * 3 * 8);
}

TEST(ImageIoDds, DataIsFaceAfterFaceEachWithItsMips) {
    const auto texture = smallCubeTexture();
    const auto file = smallCube();
    const auto expectAt = [&](size_t offset, uint32_t face, uint32_t mip) {
        const size_t bytes = texture.faceBytes(mip);
        EXPECT_EQ(std::memcmp(file.data() + offset, texture.levels[mip].data() + face * bytes, bytes), 0)
            << "face " << face << " mip " << mip << " at " << offset;
    };
    expectAt(148, 0, 0);
    expectAt(148 + 128, 0, 1);
    expectAt(148 + 128 + 32, 0, 2);
    expectAt(148 + 168, 1, 0);
    expectAt(148 + 5 * 168 + 128 + 32, 5, 2);
}

TEST(ImageIoDds, ReadsLegacyFourCcFiles) {
    for (const auto& [format, fourCc] : {std::pair{PixelFormat::Rgba16Float, 113u}, std::pair{PixelFormat::Rgba32Float, 116u},
                                         std::pair{PixelFormat::Rg16Float, 112u}, std::pair{PixelFormat::Rg32Float, 115u}}) {
        for (uint32_t faces : {1u, 6u}) {
            const auto texture = patternedTexture(format, 4, 4, faces, 2);
            const auto read = decodeDds(legacy(encodeDds(texture), fourCc), "legacy.dds");
            EXPECT_EQ(read.format, format) << fourCc;
            EXPECT_EQ(read.faces, faces) << fourCc;
            EXPECT_TRUE(read.levels == texture.levels) << fourCc;
        }
    }
}

TEST(ImageIoDds, MipCountZeroMeansOneLevel) {
    const auto texture = patternedTexture(PixelFormat::Rg16Float, 4, 2, 1, 1);
    EXPECT_TRUE(decodeDds(poked<uint32_t>(encodeDds(texture), 28, 0), "zero.dds").levels == texture.levels);
}

TEST(ImageIoDdsReader, RefusesEveryTruncatedFile) {
    const auto file = smallCube();
    EXPECT_EQ(ddsError({}), "'bad.dds' is empty");
    EXPECT_EQ(ddsError(testing::prefix(file, 100)), "'bad.dds' is truncated: the header needs 116 bytes, the file has 100");
    EXPECT_EQ(ddsError(testing::prefix(file, 130)), "'bad.dds' is truncated: the DX10 header needs 132 bytes, the file has 130");
    EXPECT_EQ(ddsError(testing::prefix(file, file.size() - 1)),
              "'bad.dds' is truncated: the texel data needs 1156 bytes, the file has 1155");
    for (size_t length = 0; length < file.size(); ++length)
        EXPECT_NE(ddsError(testing::prefix(file, length)).find("'bad.dds'"), std::string::npos) << "cut at " << length;
}

TEST(ImageIoDdsReader, RefusesFilesThatAreNotDds) {
    EXPECT_EQ(ddsError(testing::bytesOf("\x89PNG\r\n\x1a\n and the rest")), "'bad.dds' is not a DDS file (it does not start with \"DDS \")");
    EXPECT_EQ(ddsError(poked<uint32_t>(smallCube(), 4, 100)), "'bad.dds' has a header size of 100; DDS_HEADER has 124");
    EXPECT_EQ(ddsError(poked<uint32_t>(smallCube(), 76, 24)), "'bad.dds' has a pixel format size of 24; DDS_PIXELFORMAT has 32");
}

TEST(ImageIoDdsReader, NamesUnsupportedFormats) {
    EXPECT_EQ(ddsError(poked<uint32_t>(smallCube(), 128, 28)),
              "'bad.dds' has DXGI format 28 (R8G8B8A8_UNORM); supported: DX10 with DXGI format 10 (R16G16B16A16_FLOAT), "
              "2 (R32G32B32A32_FLOAT), 34 (R16G16_FLOAT) or 16 (R32G32_FLOAT), or the FourCC 113, 116, 112 or 115");
    EXPECT_NE(ddsError(poked<uint32_t>(smallCube(), 128, 95)).find("DXGI format 95 (BC6H_UF16)"), std::string::npos);
    EXPECT_NE(ddsError(poked(smallCube(), 84, std::array<char, 4>{'D', 'X', 'T', '5'})).find("has FourCC 'DXT5'; supported:"),
              std::string::npos);
    EXPECT_NE(ddsError(poked<uint32_t>(smallCube(), 84, 114)).find("has FourCC 114;"), std::string::npos);
    EXPECT_NE(ddsError(poked<uint32_t>(smallCube(), 80, 0x41)).find("integer RGB or luminance pixel format"), std::string::npos);
}

TEST(ImageIoDdsReader, RefusesArrays1DAnd3DTextures) {
    EXPECT_EQ(ddsError(poked<uint32_t>(smallCube(), 140, 2)),
              "'bad.dds' has arraySize 2; only single textures and single cubes are supported");
    EXPECT_NE(ddsError(poked<uint32_t>(smallCube(), 140, 0)).find("has arraySize 0"), std::string::npos);
    EXPECT_NE(ddsError(poked<uint32_t>(smallCube(), 132, 2)).find("is a 1D texture"), std::string::npos);
    EXPECT_NE(ddsError(poked<uint32_t>(smallCube(), 132, 4)).find("is a 3D texture"), std::string::npos);
    EXPECT_NE(ddsError(poked<uint32_t>(smallCube(), 132, 1)).find("resourceDimension 1, which is not a texture"), std::string::npos);
    EXPECT_NE(ddsError(poked<uint32_t>(smallCube(), 8, 0x80100F)).find("is a volume texture"), std::string::npos);
    EXPECT_NE(ddsError(poked<uint32_t>(legacy(smallCube(), 113), 112, 0x200 | 0x400 | 0x800)).find("is a cube without all six faces"),
              std::string::npos);
}

TEST(ImageIoDdsReader, RefusesInconsistentFiles) {
    EXPECT_NE(ddsError(poked<uint32_t>(smallCube(), 16, 8)).find("is a cube with faces that are not square (8x4)"), std::string::npos);
    EXPECT_EQ(ddsError(poked<uint32_t>(smallCube(), 28, 5)), "'bad.dds' has 5 mips; a 4x4 texture has at most 3");
    EXPECT_NE(ddsError(poked<uint32_t>(smallCube(), 12, 0)).find("width or height of 0"), std::string::npos);
    auto longer = smallCube();
    longer.push_back(std::byte{0});
    EXPECT_EQ(ddsError(longer), "'bad.dds' is longer than its header describes: 1 byte after the texel data, which ends at byte 1156");
    // A 2D file that claims to be a cube needs six times the data.
    EXPECT_NE(ddsError(poked<uint32_t>(encodeDds(patternedTexture(PixelFormat::Rg16Float, 4, 4, 1, 1)), 136, 4)).find("truncated"),
              std::string::npos);
}

} // namespace
} // namespace iblkit::image_io
