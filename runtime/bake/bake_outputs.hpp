#pragma once

#include "bake_settings.hpp"
#include "texture.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::bake {

struct WrittenFile {
    std::string name; // relative to the bake folder
    std::string sha256;
    size_t bytes;
};

// A baked texture as floats (order mip, face, row, column, channel) on its way to the files.
struct BakedTexture {
    std::string name; // "specular": specular.ktx2, specular.dds, exr/specular_mip0_px.exr ...
    image_io::PixelFormat format; // of the KTX2 and DDS files; EXR files keep 32-bit floats
    uint32_t size;
    uint32_t faces;
    uint32_t mips;
    std::vector<float> values; // channelCount(format) per texel
    std::map<std::string, std::string> keyValues = {}; // the KTX2 file's key/value data beside KTXwriter
};

// What clamping a texture to the half range cost.
struct HalfRangeClamp {
    std::string texture;
    size_t values = 0;     // clamped to ±65504
    uint32_t worstMip = 0; // the mip that lost the largest share of its energy
    double worstShare = 0; // that share: the clamped excess over the sum of |RGB|, texels weighted by solid angle
};

// Values beyond half range in a 16-bit texture (an unclipped sun copied into specular mip 0; the
// mips above are prefiltered from the 32-bit source and keep its energy): clamped to ±65504, or
// with `strict` refused (BakeError naming the texture, the count, the largest and where the first
// is). Returns nothing for a texture with none.
std::optional<HalfRangeClamp> applyHalfRangePolicy(BakedTexture& texture, bool strict);

// Writes name.ktx2, with --dds name.dds, with --exr every face and mip under exr/.
std::vector<WrittenFile> writeTexture(const std::filesystem::path& folder, const BakedTexture& texture,
                                      const ResolvedSettings& settings, const std::string& writer);

WrittenFile writeBytes(const std::filesystem::path& folder, const std::string& name, std::span<const std::byte> bytes);

} // namespace iblkit::bake
