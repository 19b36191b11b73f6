#include "byte_io.hpp"
#include "dds.hpp"
#include "dds_format.hpp"
#include "texture_shape.hpp"

namespace iblkit::image_io {
namespace {

using namespace dds;

void putHeader(ByteWriter& out, const Texture& texture) {
    const bool cube = texture.faces == 6, mipmapped = texture.mips > 1;
    out.put(kMagic);
    out.put(kHeaderSize);
    out.put(kFlagCaps | kFlagHeight | kFlagWidth | kFlagPitch | kFlagPixelFormat | kFlagMipMapCount);
    out.put(texture.height);
    out.put(texture.width);
    out.put(texture.width * bytesPerTexel(texture.format)); // pitch: bytes per row of mip 0
    out.put<uint32_t>(0);                                   // depth
    out.put(texture.mips);
    out.putZeros(11 * 4); // dwReserved1
    out.put(kPixelFormatSize);
    out.put(kPixelFormatFourCc);
    out.put(kFourCcDx10);
    out.putZeros(5 * 4); // RGB bit count and masks: unused with a FourCC
    // DDSCAPS_COMPLEX marks a file of more than one surface: mips or cube faces.
    out.put(kCapsTexture | (mipmapped || cube ? kCapsComplex : 0u) | (mipmapped ? kCapsMipMap : 0u));
    out.put(cube ? kCaps2Cubemap | kCaps2AllFaces : 0u);
    out.putZeros(3 * 4); // dwCaps3, dwCaps4, dwReserved2
}

void putDx10Header(ByteWriter& out, const Texture& texture) {
    const bool cube = texture.faces == 6;
    out.put(dxgiFormatOf(texture.format));
    out.put(kDimensionTexture2D);
    out.put(cube ? kMiscTextureCube : 0u);
    out.put<uint32_t>(1); // arraySize: one texture, or one cube of six faces
    out.put<uint32_t>(0); // miscFlags2: DDS_ALPHA_MODE_UNKNOWN
}

} // namespace

std::vector<std::byte> encodeDds(const Texture& texture) {
    requireConsistent(texture, "encodeDds");
    ByteWriter out;
    putHeader(out, texture);
    putDx10Header(out, texture);
    for (uint32_t face = 0; face < texture.faces; ++face) // Direct3D's subresource order
        for (uint32_t mip = 0; mip < texture.mips; ++mip) {
            const size_t faceBytes = texture.faceBytes(mip);
            out.putBytes(std::span(texture.levels[mip]).subspan(face * faceBytes, faceBytes));
        }
    return out.take();
}

} // namespace iblkit::image_io
