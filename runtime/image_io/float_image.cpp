#include "float_image.hpp"
#include "files.hpp"

#include "file_names.hpp"
#include "image_error.hpp"

namespace iblkit::image_io {

namespace {

// Checked before the file is opened, so that an unsupported name is named as such.
void requireFloatImageName(const std::filesystem::path& path) {
    const auto extension = lowerExtension(path);
    if (extension != ".hdr" && extension != ".pic" && extension != ".exr")
        throw ImageError("unsupported image format " + describedExtension(path) + " for " + quoted(path) +
                         " (supported: .hdr, .exr)");
}

} // namespace

FloatImage readFloatImage(const std::filesystem::path& path) {
    requireFloatImageName(path);
    return decodeFloatImage(readFileBytes(path), path);
}

FloatImage decodeFloatImage(std::span<const std::byte> bytes, const std::filesystem::path& path) {
    requireFloatImageName(path);
    return lowerExtension(path) == ".exr" ? decodeExr(bytes, path) : decodeRadianceHdr(bytes, path);
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
