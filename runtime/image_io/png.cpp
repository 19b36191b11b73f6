#include "file_names.hpp"
#include "float_image.hpp"
#include "image_error.hpp"

#include <stb_image_write.h>

#include <cerrno>
#include <climits>
#include <cstring>

namespace iblkit::image_io {

std::string encodePng(uint32_t width, uint32_t height, std::span<const uint8_t> rgba8) {
    const auto fail = [&](const std::string& why) { throw ImageError("cannot encode a PNG: " + why); };
    if (width == 0 || height == 0 || width > INT_MAX / 4 || height > INT_MAX)
        fail("the image is " + std::to_string(width) + "x" + std::to_string(height));
    if (rgba8.size() != size_t(width) * height * 4)
        fail(std::to_string(rgba8.size()) + " bytes given; " + std::to_string(width) + "x" + std::to_string(height) +
             " RGBA8 needs " + std::to_string(size_t(width) * height * 4));
    std::string png;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
    };
    if (!stbi_write_png_to_func(append, &png, int(width), int(height), 4, rgba8.data(), int(width * 4)))
        fail("stb_image_write failed");
    return png;
}

void writePng(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const uint8_t> rgba8) {
    const auto fail = [&](const std::string& why) { throw ImageError("cannot write " + quoted(path) + ": " + why); };
    if (width == 0 || height == 0 || width > INT_MAX / 4 || height > INT_MAX)
        fail("the image is " + std::to_string(width) + "x" + std::to_string(height));
    const size_t expected = size_t(width) * height * 4;
    if (rgba8.size() != expected)
        fail(std::to_string(rgba8.size()) + " bytes given; " + std::to_string(width) + "x" + std::to_string(height) +
             " RGBA8 needs " + std::to_string(expected));
    errno = 0;
    if (!stbi_write_png(path.c_str(), int(width), int(height), 4, rgba8.data(), int(width * 4)))
        fail(errno ? std::strerror(errno) : "stb_image_write failed");
}

} // namespace iblkit::image_io
