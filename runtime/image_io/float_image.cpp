#include "float_image.hpp"

#include "file_names.hpp"
#include "image_error.hpp"

namespace iblkit::image_io {

FloatImage readFloatImage(const std::filesystem::path& path) {
    const auto extension = lowerExtension(path);
    if (extension == ".hdr" || extension == ".pic") return readRadianceHdr(path);
    if (extension == ".exr") return readExr(path);
    throw ImageError("unsupported image format " + describedExtension(path) + " for " + quoted(path) +
                     " (supported: .hdr, .exr)");
}

std::vector<float> rgbaValues(const FloatImage& image) {
    if (image.channels == 4) return image.values;
    std::vector<float> rgba;
    rgba.reserve(size_t(image.width) * image.height * 4);
    for (size_t texel = 0; texel < size_t(image.width) * image.height; ++texel) {
        const float* at = &image.values[texel * image.channels];
        rgba.insert(rgba.end(), {at[0], at[1], at[2], 1.f});
    }
    return rgba;
}

} // namespace iblkit::image_io
