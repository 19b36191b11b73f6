#include "profiles/cube_frame.hpp"
#include "reference/cube_environment.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace iblkit::profiles {
namespace {

void arrangeLevel(CubeFrame frame, std::span<float> level, uint32_t size, uint32_t channels) {
    const std::vector<float> kit(level.begin(), level.end());
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t row = 0; row < size; ++row)
            for (uint32_t column = 0; column < size; ++column) {
                // A mirror maps texel centres onto texel centres: the source is one whole texel.
                const auto file = reference::cubeTexelDirection(face, column, row, size);
                const auto source = reference::cubeTexelOf(kitDirectionOf(frame, file), size);
                const size_t from = ((size_t(source.face) * size + source.row) * size + source.column) * channels;
                const size_t to = ((size_t(face) * size + row) * size + column) * channels;
                std::copy_n(kit.begin() + std::ptrdiff_t(from), channels, level.begin() + std::ptrdiff_t(to));
            }
}

} // namespace

glm::dvec3 kitDirectionOf(CubeFrame frame, glm::dvec3 fileDirection) {
    if (frame == CubeFrame::MirroredX) fileDirection.x = -fileDirection.x;
    if (frame == CubeFrame::MirroredZ) fileDirection.z = -fileDirection.z;
    return fileDirection;
}

void arrangeCube(CubeFrame frame, std::span<float> values, uint32_t size, uint32_t mips, uint32_t channels) {
    if (frame == CubeFrame::Kit) return;
    size_t offset = 0;
    for (uint32_t mip = 0; mip < mips; ++mip) {
        const uint32_t levelSize = std::max(size >> mip, 1u);
        const size_t levelValues = size_t(levelSize) * levelSize * 6 * channels;
        if (offset + levelValues > values.size()) throw std::invalid_argument("arrangeCube: fewer texels than the chain holds");
        arrangeLevel(frame, values.subspan(offset, levelValues), levelSize, channels);
        offset += levelValues;
    }
}

} // namespace iblkit::profiles
