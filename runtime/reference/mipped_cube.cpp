#include "mipped_cube.hpp"

#include <stdexcept>
#include <string>

namespace iblkit::reference {

std::span<const float> MippedCube::mip(uint32_t level) const {
    size_t offset = 0;
    for (uint32_t above = 0; above < level; ++above) offset += size_t(6) * mipSize(above) * mipSize(above) * 4;
    const size_t count = size_t(6) * mipSize(level) * mipSize(level) * 4;
    if (offset + count > texels.size())
        throw std::out_of_range("MippedCube: mip " + std::to_string(level) + " is past the " + std::to_string(mips) + " it holds");
    return std::span(texels).subspan(offset, count);
}

} // namespace iblkit::reference
