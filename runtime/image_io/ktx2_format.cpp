#include "ktx2_format.hpp"

#include <numeric>

namespace iblkit::image_io::ktx2 {

uint32_t vkFormatOf(PixelFormat format) {
    switch (format) {
    case PixelFormat::Rgba16Float: return 97;
    case PixelFormat::Rgba32Float: return 109;
    case PixelFormat::Rg16Float: return 83;
    case PixelFormat::Rg32Float: return 103;
    }
    return 0;
}

std::optional<PixelFormat> formatOfVkFormat(uint32_t vkFormat) {
    for (auto format : {PixelFormat::Rgba16Float, PixelFormat::Rgba32Float, PixelFormat::Rg16Float, PixelFormat::Rg32Float})
        if (vkFormatOf(format) == vkFormat) return format;
    return std::nullopt;
}

size_t levelAlignment(PixelFormat format) { return std::lcm(size_t(bytesPerTexel(format)), size_t(4)); }

} // namespace iblkit::image_io::ktx2
