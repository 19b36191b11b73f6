#include "dds_validator.hpp"
#include "violations.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <map>

namespace iblkit::testing {
namespace {

// Microsoft's documentation, restated here on purpose rather than shared with the writer.
constexpr uint32_t DDSD_CAPS = 0x1, DDSD_HEIGHT = 0x2, DDSD_WIDTH = 0x4, DDSD_PITCH = 0x8, DDSD_PIXELFORMAT = 0x1000,
                   DDSD_MIPMAPCOUNT = 0x20000, DDSD_LINEARSIZE = 0x80000, DDSD_DEPTH = 0x800000;
constexpr uint32_t DDPF_FOURCC = 0x4;
constexpr uint32_t DDSCAPS_COMPLEX = 0x8, DDSCAPS_TEXTURE = 0x1000, DDSCAPS_MIPMAP = 0x400000;
constexpr uint32_t DDSCAPS2_CUBEMAP = 0x200, DDSCAPS2_CUBEMAP_ALLFACES = 0xFC00, DDSCAPS2_VOLUME = 0x200000;
constexpr uint32_t DDS_DIMENSION_TEXTURE2D = 3, DDS_RESOURCE_MISC_TEXTURECUBE = 0x4, DDS_ALPHA_MODE_CUSTOM = 4;
constexpr size_t kMagicBytes = 4, kHeaderBytes = 124, kDx10HeaderBytes = 20;
constexpr size_t kDataOffset = kMagicBytes + kHeaderBytes + kDx10HeaderBytes;

// DXGI_FORMAT -> bits per pixel, for the float formats this checks.
const std::map<uint32_t, uint32_t> kBitsPerPixel = {{10, 64}, {2, 128}, {34, 32}, {16, 64}};

// The structures' fields, at their offsets in the file (after the magic).
struct Fields {
    uint32_t size, flags, height, width, pitchOrLinearSize, depth, mipMapCount;
    uint32_t pfSize, pfFlags, pfFourCc, caps, caps2;
    uint32_t dxgiFormat, resourceDimension, miscFlag, arraySize, miscFlags2;
};

Fields readFields(std::span<const std::byte> file) {
    const auto at = [&](size_t offset) {
        uint32_t value;
        std::memcpy(&value, file.data() + offset, sizeof value);
        return value;
    };
    return {at(4),   at(8),   at(12),  at(16),  at(20),  at(24),  at(28),  at(76),  at(80),
            at(84),  at(108), at(112), at(128), at(132), at(136), at(140), at(144)};
}

void checkHeader(const Fields& f, Violations& v) {
    v.expect(f.size == 124, "dwSize: must be 124, is " + std::to_string(f.size));
    const uint32_t required = DDSD_CAPS | DDSD_HEIGHT | DDSD_WIDTH | DDSD_PIXELFORMAT;
    v.expect((f.flags & required) == required, "dwFlags: must have DDSD_CAPS, DDSD_HEIGHT, DDSD_WIDTH and DDSD_PIXELFORMAT");
    v.expect(f.pfSize == 32, "DDS_PIXELFORMAT dwSize: must be 32, is " + std::to_string(f.pfSize));
    v.expect(f.pfFlags == DDPF_FOURCC, "DDS_PIXELFORMAT dwFlags: must be DDPF_FOURCC");
    v.expect(f.pfFourCc == 0x30315844, "DDS_PIXELFORMAT dwFourCC: must be \"DX10\"");
    v.expect(f.caps & DDSCAPS_TEXTURE, "dwCaps: must have DDSCAPS_TEXTURE");
    v.expect(f.depth == 0 && !(f.flags & DDSD_DEPTH) && !(f.caps2 & DDSCAPS2_VOLUME), "dwDepth: a 2D texture has no depth");
    v.expect(f.width > 0 && f.height > 0, "dwWidth/dwHeight: must not be 0");
}

void checkDx10Header(const Fields& f, Violations& v) {
    v.expect(f.resourceDimension == DDS_DIMENSION_TEXTURE2D, "resourceDimension: must be DDS_DIMENSION_TEXTURE2D (3)");
    v.expect((f.miscFlag & ~DDS_RESOURCE_MISC_TEXTURECUBE) == 0, "miscFlag: only DDS_RESOURCE_MISC_TEXTURECUBE may be set");
    v.expect(f.arraySize == 1, "arraySize: must be 1 (one texture, or one cube), is " + std::to_string(f.arraySize));
    v.expect(f.miscFlags2 <= DDS_ALPHA_MODE_CUSTOM, "miscFlags2: must be a DDS_ALPHA_MODE");
}

void checkCube(const Fields& f, bool cube, Violations& v) {
    if (cube) {
        v.expect((f.caps2 & (DDSCAPS2_CUBEMAP | DDSCAPS2_CUBEMAP_ALLFACES)) == (DDSCAPS2_CUBEMAP | DDSCAPS2_CUBEMAP_ALLFACES),
                 "dwCaps2: a cube must have DDSCAPS2_CUBEMAP and all six faces");
        v.expect(f.caps & DDSCAPS_COMPLEX, "dwCaps: a cube must have DDSCAPS_COMPLEX (more than one surface)");
        v.expect(f.width == f.height, "dwWidth/dwHeight: cube faces must be square");
    } else {
        v.expect(f.caps2 == 0, "dwCaps2: must be 0 unless miscFlag marks a cube");
    }
}

void checkMips(const Fields& f, uint32_t mips, Violations& v) {
    if (mips > 1) {
        v.expect(f.flags & DDSD_MIPMAPCOUNT, "dwFlags: a mipmapped texture must have DDSD_MIPMAPCOUNT");
        v.expect((f.caps & (DDSCAPS_MIPMAP | DDSCAPS_COMPLEX)) == (DDSCAPS_MIPMAP | DDSCAPS_COMPLEX),
                 "dwCaps: a mipmapped texture must have DDSCAPS_MIPMAP and DDSCAPS_COMPLEX");
    }
    const uint32_t maxMips = uint32_t(std::bit_width(std::max(f.width, f.height)));
    v.expect(mips <= maxMips, "dwMipMapCount: " + std::to_string(mips) + " exceeds the " + std::to_string(maxMips) + " mips down to 1x1");
}

void checkPitch(const Fields& f, uint32_t bitsPerPixel, Violations& v) {
    v.expect((f.flags & DDSD_PITCH) && !(f.flags & DDSD_LINEARSIZE), "dwFlags: an uncompressed texture must have DDSD_PITCH");
    // Microsoft's formula for uncompressed formats: (width * bits-per-pixel + 7) / 8.
    const uint64_t pitch = (uint64_t(f.width) * bitsPerPixel + 7) / 8;
    v.expect(f.pitchOrLinearSize == pitch, "dwPitchOrLinearSize: must be the row pitch " + std::to_string(pitch));
}

void checkSize(size_t fileSize, const Fields& f, uint32_t faces, uint32_t mips, uint32_t bitsPerPixel, Violations& v) {
    uint64_t expected = kDataOffset;
    for (uint32_t face = 0; face < faces; ++face)
        for (uint32_t mip = 0; mip < std::min(mips, 32u); ++mip)
            expected += uint64_t(std::max(1u, f.width >> mip)) * std::max(1u, f.height >> mip) * bitsPerPixel / 8;
    v.expect(fileSize == expected, "file size: the headers and every face's mips need " + std::to_string(expected) +
                                       " bytes, the file has " + std::to_string(fileSize));
}

} // namespace

std::vector<std::string> validateDds(std::span<const std::byte> file) {
    if (file.size() < kDataOffset)
        return {"file size: " + std::to_string(file.size()) + " bytes, fewer than the magic, DDS_HEADER and DDS_HEADER_DXT10 (148)"};
    if (std::memcmp(file.data(), "DDS ", 4) != 0) return {"magic: the file must start with \"DDS \""};
    const Fields fields = readFields(file);
    const auto bits = kBitsPerPixel.find(fields.dxgiFormat);
    if (bits == kBitsPerPixel.end()) return {"dxgiFormat: " + std::to_string(fields.dxgiFormat) + " is not one this validator checks"};
    Violations violations;
    const bool cube = fields.miscFlag & DDS_RESOURCE_MISC_TEXTURECUBE;
    const uint32_t mips = std::max(1u, fields.mipMapCount);
    checkHeader(fields, violations);
    checkDx10Header(fields, violations);
    checkCube(fields, cube, violations);
    checkMips(fields, mips, violations);
    checkPitch(fields, bits->second, violations);
    checkSize(file.size(), fields, cube ? 6 : 1, mips, bits->second, violations);
    return violations.take();
}

} // namespace iblkit::testing
