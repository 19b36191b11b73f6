#include "image_save.hpp"

#include "float_image.hpp"
#include "run_error.hpp"

#include <algorithm>
#include <cmath>

namespace iblkit::run {
namespace {

std::string lowerExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

double encodeSrgb(double linear) {
    const double clamped = std::clamp(linear, 0.0, 1.0);
    return clamped <= 0.0031308 ? clamped * 12.92 : 1.055 * std::pow(clamped, 1.0 / 2.4) - 0.055;
}

// Texel t's channel c in RGBA: one channel is grey, a missing blue 0 and a missing alpha 1.
double rgbaChannel(const std::vector<double>& values, uint32_t channels, size_t texel, uint32_t c) {
    if (c == 3) return channels == 4 ? values[texel * 4 + 3] : 1.0;
    if (channels == 1) return values[texel];
    return c < channels ? values[texel * channels + c] : 0.0;
}

} // namespace

bool isPictureFile(const std::filesystem::path& path) {
    const auto extension = lowerExtension(path);
    return extension == ".png" || extension == ".exr";
}

std::string encodePicture(const std::filesystem::path& path, const vulkan::TexelFormat& format, const std::vector<double>& values,
                          uint32_t width, uint32_t height, uint32_t layers, uint32_t mips) {
    const auto fail = [&](const std::string& why) { throw RunError(path.string() + ": error: " + why); };
    if (format.kind == vulkan::ComponentKind::UInt || format.kind == vulkan::ComponentKind::SInt)
        fail(std::string(format.name) + " holds integers, not colours: save it as .npy");
    if (layers != 1 || mips != 1)
        fail("a picture holds one 2D image, and this one has " + std::to_string(layers) + " layers and " + std::to_string(mips) +
             " mips: save it as .npy");
    const size_t texels = size_t(width) * height;
    if (lowerExtension(path) == ".exr") {
        image_io::FloatImage image{width, height, 4, std::vector<float>(texels * 4)};
        for (size_t t = 0; t < texels; ++t)
            for (uint32_t c = 0; c < 4; ++c) image.values[t * 4 + c] = float(rgbaChannel(values, format.channels, t, c));
        return image_io::encodeExr(image, path);
    }
    const bool unorm = format.kind == vulkan::ComponentKind::UNorm;
    std::vector<uint8_t> rgba(texels * 4);
    for (size_t t = 0; t < texels; ++t)
        for (uint32_t c = 0; c < 4; ++c) {
            const double value = rgbaChannel(values, format.channels, t, c);
            rgba[t * 4 + c] = uint8_t(std::lround(255.0 * (unorm || c == 3 ? std::clamp(value, 0.0, 1.0) : encodeSrgb(value))));
        }
    return image_io::encodePng(width, height, rgba);
}

} // namespace iblkit::run
