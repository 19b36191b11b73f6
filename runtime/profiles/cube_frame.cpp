#include "profiles/cube_frame.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace iblkit::profiles {
namespace {

struct TexelAddress {
    uint32_t face, column, row;
};

// The Vulkan cube map convention: the direction through texel coordinates (s, t) in [-1, 1] of a face.
glm::dvec3 directionOf(uint32_t face, double s, double t) {
    switch (face) {
    case 0: return {1, -t, -s};
    case 1: return {-1, -t, s};
    case 2: return {s, 1, t};
    case 3: return {s, -1, -t};
    case 4: return {s, -t, 1};
    default: return {-s, -t, -1};
    }
}

// The texel a direction through a texel centre selects; a mirror maps centres onto centres, so
// rounding recovers the exact texel.
TexelAddress texelOf(const glm::dvec3& d, uint32_t size) {
    const glm::dvec3 a = glm::abs(d);
    uint32_t face;
    double s, t;
    if (a.x >= a.y && a.x >= a.z) {
        face = d.x > 0 ? 0 : 1;
        s = d.x > 0 ? -d.z / a.x : d.z / a.x;
        t = -d.y / a.x;
    } else if (a.y >= a.z) {
        face = d.y > 0 ? 2 : 3;
        s = d.x / a.y;
        t = d.y > 0 ? d.z / a.y : -d.z / a.y;
    } else {
        face = d.z > 0 ? 4 : 5;
        s = d.z > 0 ? d.x / a.z : -d.x / a.z;
        t = -d.y / a.z;
    }
    const auto index = [size](double coordinate) {
        return uint32_t(std::clamp(std::lround((coordinate + 1) * 0.5 * size - 0.5), 0l, long(size) - 1));
    };
    return {face, index(s), index(t)};
}

void arrangeLevel(CubeFrame frame, std::span<float> level, uint32_t size, uint32_t channels) {
    const std::vector<float> kit(level.begin(), level.end());
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t row = 0; row < size; ++row)
            for (uint32_t column = 0; column < size; ++column) {
                const double s = (column + 0.5) / size * 2 - 1, t = (row + 0.5) / size * 2 - 1;
                const auto source = texelOf(kitDirectionOf(frame, directionOf(face, s, t)), size);
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
