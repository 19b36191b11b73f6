#include "bake_outputs.hpp"

#include "bake_error.hpp"
#include "cube_geometry.hpp"
#include "dds.hpp"
#include "float_image.hpp"
#include "ktx1.hpp"
#include "ktx2.hpp"
#include "sha256.hpp"
#include "texel_checks.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cerrno>
#include <fstream>

namespace iblkit::bake {
namespace {

namespace fs = std::filesystem;

constexpr std::array<const char*, 6> kFaceNames = {"px", "nx", "py", "ny", "pz", "nz"};

uint32_t mipSize(const BakedTexture& texture, uint32_t mip) { return std::max(1u, texture.size >> mip); }

size_t levelOffset(const BakedTexture& texture, uint32_t mip) {
    size_t offset = 0;
    for (uint32_t level = 0; level < mip; ++level) offset += size_t(mipSize(texture, level)) * mipSize(texture, level);
    return offset * texture.faces * image_io::channelCount(texture.format);
}

// The share of one mip's energy that clamping to the half range takes away: the excess of each
// colour value past 65504 over the sum of |value|, each texel weighted by its solid angle on a cube.
double halfRangeLoss(const BakedTexture& texture, uint32_t mip) {
    const uint32_t channels = image_io::channelCount(texture.format), size = mipSize(texture, mip);
    const float* values = texture.values.data() + levelOffset(texture, mip);
    const float* end = texture.values.data() + levelOffset(texture, mip + 1);
    // Most mips lose nothing; only those that do pay for the solid angles.
    if (std::none_of(values, end, [](float value) { return std::abs(value) > kLargestHalf; })) return 0;
    double total = 0, lost = 0;
    for (uint32_t face = 0; face < texture.faces; ++face)
        for (uint32_t row = 0; row < size; ++row)
            for (uint32_t column = 0; column < size; ++column) {
                const double weight = texture.faces == 6 ? reference::CubeTexelSolidAngle<double>(column, row, size) : 1.0;
                const float* texel = values + ((size_t(face) * size + row) * size + column) * channels;
                for (uint32_t c = 0; c < std::min(channels, 3u); ++c) {
                    total += weight * std::abs(double(texel[c]));
                    lost += weight * std::max(0.0, std::abs(double(texel[c])) - double(kLargestHalf));
                }
            }
    return total > 0 ? lost / total : 0;
}

std::string locate(const BakedTexture& texture, size_t valueIndex) {
    const uint32_t channels = image_io::channelCount(texture.format);
    uint32_t mip = 0;
    while (mip + 1 < texture.mips && levelOffset(texture, mip + 1) <= valueIndex) ++mip;
    const size_t texel = (valueIndex - levelOffset(texture, mip)) / channels, size = mipSize(texture, mip);
    return fmt::format("mip {}, face {}, row {}, column {}", mip, kFaceNames[texel / (size * size)], texel / size % size,
                       texel % size);
}

void writeFile(const fs::path& path, std::span<const std::span<const std::byte>> pieces) {
    std::ofstream stream(path, std::ios::binary);
    for (const auto bytes : pieces) stream.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    stream.close(); // a full disk may first show when the last bytes are written
    if (stream.fail())
        throw BakeError("cannot write '" + path.string() + "': " + std::generic_category().message(errno));
}

// A file of pieces written one after another: a texture's levels are written from its own bytes,
// not first copied into one buffer (fresh memory is slow to touch the first time).
WrittenFile writePieces(const fs::path& folder, const std::string& name, std::span<const std::span<const std::byte>> pieces) {
    writeFile(folder / name, pieces);
    std::vector<std::string_view> text;
    size_t size = 0;
    for (const auto bytes : pieces) {
        text.emplace_back(reinterpret_cast<const char*>(bytes.data()), bytes.size());
        size += bytes.size();
    }
    return {name, cache::sha256Hex(std::span<const std::string_view>(text)), size};
}

WrittenFile describe(const fs::path& folder, const std::string& name) {
    std::error_code error;
    const auto bytes = fs::file_size(folder / name, error);
    return {name, cache::sha256OfFile(folder / name), size_t(bytes)};
}

std::vector<WrittenFile> writeExrFaces(const fs::path& folder, const BakedTexture& texture) {
    fs::create_directories(folder / "exr");
    const uint32_t channels = image_io::channelCount(texture.format);
    std::vector<WrittenFile> written;
    for (uint32_t mip = 0; mip < texture.mips; ++mip)
        for (uint32_t face = 0; face < texture.faces; ++face) {
            const uint32_t size = mipSize(texture, mip);
            image_io::FloatImage image{size, size, channels == 2 ? 3u : channels, {}};
            const float* start = texture.values.data() + levelOffset(texture, mip) + size_t(face) * size * size * channels;
            for (size_t texel = 0; texel < size_t(size) * size; ++texel) {
                image.values.insert(image.values.end(), start + texel * channels, start + (texel + 1) * channels);
                if (channels == 2) image.values.push_back(0.f); // EXR has no two-channel RGB layout: blue is 0
            }
            std::string name = "exr/" + texture.name;
            if (texture.mips > 1) name += "_mip" + std::to_string(mip);
            if (texture.faces == 6) name += std::string("_") + kFaceNames[face];
            name += ".exr";
            image_io::writeExr(folder / name, image);
            written.push_back(describe(folder, name));
        }
    return written;
}

} // namespace

std::optional<HalfRangeClamp> applyHalfRangePolicy(BakedTexture& texture, bool strict) {
    if (image_io::bytesPerChannel(texture.format) != 2) return std::nullopt;
    const auto overflow = findHalfOverflow(texture.values);
    if (overflow.count == 0) return std::nullopt;
    if (strict)
        throw BakeError(fmt::format("{}: {} values exceed the 16-bit float range (largest {:g}, the first at {}); "
                                    "bake without --strict to clamp them to 65504",
                                    texture.name, overflow.count, overflow.largest, locate(texture, overflow.firstValue)));
    HalfRangeClamp clamp{texture.name, overflow.count, 0, 0};
    for (uint32_t mip = 0; mip < texture.mips; ++mip)
        if (const double share = halfRangeLoss(texture, mip); share > clamp.worstShare) {
            clamp.worstMip = mip;
            clamp.worstShare = share;
        }
    clampToHalfRange(texture.values);
    return clamp;
}

WrittenFile writeBytes(const fs::path& folder, const std::string& name, std::span<const std::byte> bytes) {
    return writePieces(folder, name, std::span(&bytes, 1));
}

std::vector<WrittenFile> writeTexture(const fs::path& folder, const BakedTexture& texture, const ResolvedSettings& settings,
                                      const std::string& writer) {
    const auto gpuTexture =
        image_io::makeTexture(texture.format, texture.size, texture.size, texture.faces, texture.mips, texture.values);
    std::vector<WrittenFile> written{
        writePieces(folder, texture.name + ".ktx2", image_io::encodeKtx2Pieces(gpuTexture, writer, texture.keyValues).pieces)};
    const auto engineFile = settings.engineProfile->file;
    if (engineFile == profiles::SpecularFile::Ktx1)
        written.push_back(writeBytes(folder, texture.name + ".ktx", image_io::encodeKtx1(gpuTexture)));
    if (settings.dds || engineFile == profiles::SpecularFile::Dds) written.push_back(writeBytes(folder, texture.name + ".dds", image_io::encodeDds(gpuTexture)));
    if (settings.exr)
        for (auto& file : writeExrFaces(folder, texture)) written.push_back(std::move(file));
    return written;
}

} // namespace iblkit::bake
