#include "texture_shape.hpp"

#include "image_error.hpp"

#include <algorithm>
#include <bit>

namespace iblkit::image_io {

uint32_t fullMipCount(uint32_t width, uint32_t height) { return uint32_t(std::bit_width(std::max(width, height))); }

std::string shapeProblem(uint32_t width, uint32_t height, uint32_t faces, uint32_t mips) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width == 0 || height == 0) return "has a width or height of 0 (" + size + ")";
    if (width > kMaxTextureSide || height > kMaxTextureSide)
        return "is larger than " + std::to_string(kMaxTextureSide) + " texels on a side (" + size + ")";
    if (faces != 1 && faces != 6) return "has " + std::to_string(faces) + " faces; supported: 1, or 6 for a cube";
    if (faces == 6 && width != height) return "is a cube with faces that are not square (" + size + ")";
    if (mips == 0) return "has 0 mips";
    if (mips > fullMipCount(width, height))
        return "has " + std::to_string(mips) + " mips; a " + size + " texture has at most " +
               std::to_string(fullMipCount(width, height));
    return "";
}

void requireConsistent(const Texture& texture, const std::string& who) {
    const auto problem = shapeProblem(texture.width, texture.height, texture.faces, texture.mips);
    if (!problem.empty()) throw ImageError(who + ": the texture " + problem);
    if (texture.levels.size() != texture.mips)
        throw ImageError(who + ": the texture has " + std::to_string(texture.levels.size()) + " levels for " +
                         std::to_string(texture.mips) + " mips");
    for (uint32_t mip = 0; mip < texture.mips; ++mip) {
        const size_t expected = texture.faceBytes(mip) * texture.faces;
        if (texture.levels[mip].size() != expected)
            throw ImageError(who + ": mip " + std::to_string(mip) + " holds " + std::to_string(texture.levels[mip].size()) +
                             " bytes; its size needs " + std::to_string(expected));
    }
}

} // namespace iblkit::image_io
