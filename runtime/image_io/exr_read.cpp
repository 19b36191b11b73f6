#include "exr_memory_stream.hpp"
#include "file_names.hpp"
#include "files.hpp"
#include "float_image.hpp"
#include "image_error.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfRgbaFile.h>

#include <algorithm>

namespace iblkit::image_io {
namespace {

// 2^28 texels of four floats is 4 GiB: a 16384x8192 panorama fits, a corrupt header's
// billions of texels are refused before anything is allocated for them.
constexpr uint64_t kMaxTexels = uint64_t(1) << 28;

std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
}

FloatImage sizedFor(const Imath::Box2i& window, const std::filesystem::path& path) {
    const int64_t width = int64_t(window.max.x) - window.min.x + 1, height = int64_t(window.max.y) - window.min.y + 1;
    if (width <= 0 || height <= 0 || uint64_t(width) * uint64_t(height) > kMaxTexels)
        throw ImageError(quoted(path) + " has a data window of " + std::to_string(width) + "x" + std::to_string(height) +
                         " texels; supported: 1 to 2^28 texels");
    return FloatImage{uint32_t(width), uint32_t(height), 4, std::vector<float>(size_t(width) * size_t(height) * 4, 1.f)};
}

std::string channelNames(const Imf::ChannelList& channels) {
    std::string names;
    for (auto channel = channels.begin(); channel != channels.end(); ++channel)
        names += (names.empty() ? "" : ", ") + std::string(channel.name());
    return names.empty() ? "none" : names;
}

// R, G, B and A as 32-bit floats; OpenEXR converts half and uint channels and fills A with 1
// when the file has none.
FloatImage readRgba(Imf::InputFile& file, const std::filesystem::path& path) {
    const auto& window = file.header().dataWindow();
    FloatImage image = sizedFor(window, path);
    const size_t xStride = 4 * sizeof(float), yStride = xStride * image.width;
    Imf::FrameBuffer frame;
    const char* names[] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c)
        frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, image.values.data() + c, window, xStride, yStride, 1, 1,
                                                c == 3 ? 1.0 : 0.0));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return image;
}

// Luminance/chroma (Y, RY, BY) and luminance-only files, which only the RGBA interface
// converts to RGB; it reads halves, so these files are no more precise than half anyway.
FloatImage readLuminanceChroma(std::span<const std::byte> bytes, const std::filesystem::path& path) {
    ExrMemoryStream stream(bytes, path.c_str());
    Imf::RgbaInputFile file(stream);
    const auto& window = file.dataWindow();
    FloatImage image = sizedFor(window, path);
    std::vector<Imf::Rgba> pixels(size_t(image.width) * image.height);
    // OpenEXR addresses the buffer by absolute data-window coordinates.
    const ptrdiff_t origin = ptrdiff_t(window.min.x) + ptrdiff_t(window.min.y) * ptrdiff_t(image.width);
    file.setFrameBuffer(pixels.data() - origin, 1, image.width);
    file.readPixels(window.min.y, window.max.y);
    for (size_t i = 0; i < pixels.size(); ++i) {
        float* texel = &image.values[4 * i];
        texel[0] = pixels[i].r;
        texel[1] = pixels[i].g;
        texel[2] = pixels[i].b;
        texel[3] = pixels[i].a;
    }
    return image;
}

FloatImage readExrBytes(std::span<const std::byte> bytes, const std::filesystem::path& path) {
    ExrMemoryStream stream(bytes, path.c_str());
    Imf::InputFile file(stream);
    const auto& channels = file.header().channels();
    const bool rgb = channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
    if (rgb) return readRgba(file, path);
    if (channels.findChannel("Y")) return readLuminanceChroma(bytes, path);
    throw ImageError(quoted(path) + " has the channels " + channelNames(channels) +
                     "; readable: R, G, B (and A), or Y (and RY, BY); layers are not supported");
}

} // namespace

FloatImage decodeExr(std::span<const std::byte> bytes, const std::filesystem::path& name) {
    try {
        return readExrBytes(bytes, name);
    } catch (const ImageError&) {
        throw;
    } catch (const std::exception& error) {
        throw ImageError(quoted(name) + " is not a readable OpenEXR image: " + oneLine(error.what()));
    }
}

FloatImage readExr(const std::filesystem::path& path) { return decodeExr(readFileBytes(path), path); }

} // namespace iblkit::image_io
