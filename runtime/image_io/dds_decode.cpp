#include "byte_io.hpp"
#include "dds.hpp"
#include "dds_format.hpp"
#include "texture_shape.hpp"

#include <map>

namespace iblkit::image_io {
namespace {

using namespace dds;

struct Layout {
    PixelFormat format;
    bool cube;
    size_t dataOffset;
};

std::string dxgiDescription(uint32_t dxgiFormat) {
    static const std::map<uint32_t, const char*> names = {
        {6, "R32G32B32_FLOAT"}, {26, "R11G11B10_FLOAT"}, {28, "R8G8B8A8_UNORM"}, {29, "R8G8B8A8_UNORM_SRGB"},
        {41, "R32_FLOAT"}, {54, "R16_FLOAT"}, {67, "R9G9B9E5_SHAREDEXP"}, {71, "BC1_UNORM"}, {77, "BC3_UNORM"},
        {87, "B8G8R8A8_UNORM"}, {95, "BC6H_UF16"}, {96, "BC6H_SF16"}, {98, "BC7_UNORM"}};
    const auto name = names.find(dxgiFormat);
    return std::to_string(dxgiFormat) + (name == names.end() ? "" : std::string(" (") + name->second + ")");
}

std::string fourCcDescription(uint32_t fourCc) {
    std::string text;
    for (int shift = 0; shift < 32; shift += 8) {
        const char c = char((fourCc >> shift) & 0xFF);
        if (c < 0x20 || c > 0x7E) return std::to_string(fourCc);
        text += c;
    }
    return "'" + text + "'";
}

const char* kSupported = "supported: DX10 with DXGI format 10 (R16G16B16A16_FLOAT), 2 (R32G32B32A32_FLOAT), "
                         "34 (R16G16_FLOAT) or 16 (R32G32_FLOAT), or the FourCC 113, 116, 112 or 115";

Layout readDx10Layout(const ByteReader& in) {
    const auto field = [&](size_t offset) { return in.get<uint32_t>(offset, "the DX10 header"); };
    const auto format = formatOfDxgiFormat(field(kDxgiFormat));
    if (!format) in.fail("has DXGI format " + dxgiDescription(field(kDxgiFormat)) + "; " + kSupported);
    const uint32_t dimension = field(kResourceDimension);
    if (dimension == kDimensionTexture1D) in.fail("is a 1D texture; only 2D textures and cubes are supported");
    if (dimension == kDimensionTexture3D) in.fail("is a 3D texture; only 2D textures and cubes are supported");
    if (dimension != kDimensionTexture2D)
        in.fail("has resourceDimension " + std::to_string(dimension) + ", which is not a texture");
    if (field(kArraySize) != 1)
        in.fail("has arraySize " + std::to_string(field(kArraySize)) +
                "; only single textures and single cubes are supported");
    return {*format, (field(kMiscFlag) & kMiscTextureCube) != 0, kDx10HeaderEnd};
}

Layout readLegacyLayout(const ByteReader& in, uint32_t fourCc) {
    const auto format = formatOfLegacyFourCc(fourCc);
    if (!format) in.fail("has FourCC " + fourCcDescription(fourCc) + "; " + kSupported);
    const uint32_t caps2 = in.get<uint32_t>(kCaps2, "the header");
    const bool cube = (caps2 & kCaps2Cubemap) != 0;
    if (cube && (caps2 & kCaps2AllFaces) != kCaps2AllFaces) in.fail("is a cube without all six faces");
    return {*format, cube, kHeaderEnd};
}

Layout readLayout(const ByteReader& in) {
    if (in.get<uint32_t>(0, "the magic number") != kMagic) in.fail("is not a DDS file (it does not start with \"DDS \")");
    const auto field = [&](size_t offset) { return in.get<uint32_t>(offset, "the header"); };
    if (field(kSize) != kHeaderSize) in.fail("has a header size of " + std::to_string(field(kSize)) + "; DDS_HEADER has 124");
    if (field(kPixelFormat) != kPixelFormatSize)
        in.fail("has a pixel format size of " + std::to_string(field(kPixelFormat)) + "; DDS_PIXELFORMAT has 32");
    if (!(field(kPixelFormatFlags) & kPixelFormatFourCc))
        in.fail("has an integer RGB or luminance pixel format (no FourCC); " + std::string(kSupported));
    if ((field(kFlags) & kFlagDepth) || (field(kCaps2) & kCaps2Volume))
        in.fail("is a volume texture; only 2D textures and cubes are supported");
    return field(kFourCc) == kFourCcDx10 ? readDx10Layout(in) : readLegacyLayout(in, field(kFourCc));
}

} // namespace

Texture decodeDds(std::span<const std::byte> bytes, const std::string& name) {
    const ByteReader in(bytes, name);
    const Layout layout = readLayout(in);
    // Readers must not rely on DDSD_MIPMAPCOUNT being set; a count of 0 means one level.
    Texture texture{layout.format, in.get<uint32_t>(kWidth, "the header"), in.get<uint32_t>(kHeight, "the header"),
                    layout.cube ? 6u : 1u, std::max(1u, in.get<uint32_t>(kMipMapCount, "the header")), {}};
    const auto problem = shapeProblem(texture.width, texture.height, texture.faces, texture.mips);
    if (!problem.empty()) in.fail(problem);
    texture.levels.resize(texture.mips);
    size_t offset = layout.dataOffset;
    for (uint32_t face = 0; face < texture.faces; ++face)
        for (uint32_t mip = 0; mip < texture.mips; ++mip) {
            const auto data = in.slice(offset, texture.faceBytes(mip), "the texel data");
            texture.levels[mip].insert(texture.levels[mip].end(), data.begin(), data.end());
            offset += data.size();
        }
    if (offset != in.size()) {
        const size_t extra = in.size() - offset;
        in.fail("is longer than its header describes: " + std::to_string(extra) + (extra == 1 ? " byte" : " bytes") +
                " after the texel data, which ends at byte " + std::to_string(offset));
    }
    return texture;
}

} // namespace iblkit::image_io
