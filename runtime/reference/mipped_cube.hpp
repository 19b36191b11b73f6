#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

namespace iblkit::reference {

// A cube with its mips, texels as vulkan::Image uploads and downloads them: mip, face, row,
// column, RGBA.
struct MippedCube {
    uint32_t size = 0;
    uint32_t mips = 0;
    std::vector<float> texels;

    uint32_t mipSize(uint32_t mip) const { return std::max(1u, size >> mip); }
    std::span<const float> mip(uint32_t mip) const;
};

} // namespace iblkit::reference
