#include "profiles/cube_frame.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <utility>

namespace iblkit::profiles {
namespace {

// Negating x maps face +X onto -X and back, and reverses every face's columns: on each face the
// column coordinate runs along ±x (±Y, ±Z) or along ±z, whose sign flips as the face changes (±X).
void mirrorLevelX(std::span<float> level, uint32_t size, uint32_t channels) {
    const size_t row = size_t(size) * channels;
    const size_t face = row * size;
    std::swap_ranges(level.begin(), level.begin() + std::ptrdiff_t(face), level.begin() + std::ptrdiff_t(face));
    for (size_t start = 0; start < face * 6; start += row)
        for (uint32_t left = 0, right = size - 1; left < right; ++left, --right)
            std::swap_ranges(level.begin() + std::ptrdiff_t(start + left * channels),
                             level.begin() + std::ptrdiff_t(start + (left + 1) * channels),
                             level.begin() + std::ptrdiff_t(start + right * channels));
}

} // namespace

glm::dvec3 kitDirectionOf(CubeFrame frame, glm::dvec3 fileDirection) {
    if (frame == CubeFrame::MirroredX) fileDirection.x = -fileDirection.x;
    return fileDirection;
}

void arrangeCube(CubeFrame frame, std::span<float> values, uint32_t size, uint32_t mips, uint32_t channels) {
    if (frame == CubeFrame::Kit) return;
    size_t offset = 0;
    for (uint32_t mip = 0; mip < mips; ++mip) {
        const uint32_t levelSize = std::max(size >> mip, 1u);
        const size_t levelValues = size_t(levelSize) * levelSize * 6 * channels;
        if (offset + levelValues > values.size()) throw std::invalid_argument("arrangeCube: fewer texels than the chain holds");
        mirrorLevelX(values.subspan(offset, levelValues), levelSize, channels);
        offset += levelValues;
    }
}

} // namespace iblkit::profiles
