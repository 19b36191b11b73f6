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

} // namespace iblkit::image_io
