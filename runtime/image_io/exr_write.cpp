#include "file_names.hpp"
#include "exr_memory_stream.hpp"
#include "float_image.hpp"
#include "image_error.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#include <algorithm>

namespace iblkit::image_io {
namespace {

void requireWritable(const std::filesystem::path& path, const FloatImage& image) {
    const auto fail = [&](const std::string& why) { throw ImageError("cannot write " + quoted(path) + ": " + why); };
    if (image.channels != 3 && image.channels != 4)
        fail("the image has " + std::to_string(image.channels) + " channels; EXR output needs 3 or 4");
    if (image.width == 0 || image.height == 0 || image.width > INT32_MAX || image.height > INT32_MAX)
        fail("the image is " + std::to_string(image.width) + "x" + std::to_string(image.height));
    const size_t expected = size_t(image.width) * image.height * image.channels;
    if (image.values.size() != expected)
        fail("the image holds " + std::to_string(image.values.size()) + " values; " + std::to_string(image.width) + "x" +
             std::to_string(image.height) + "x" + std::to_string(image.channels) + " needs " + std::to_string(expected));
}

template <typename Destination>
void writeExrTo(const std::filesystem::path& path, const FloatImage& image, Destination& destination) {
    requireWritable(path, image);
    try {
        Imf::Header header(int(image.width), int(image.height));
        header.compression() = Imf::ZIP_COMPRESSION;
        Imf::FrameBuffer frame;
        const size_t xStride = image.channels * sizeof(float), yStride = xStride * image.width;
        const char* names[] = {"R", "G", "B", "A"};
        for (uint32_t c = 0; c < image.channels; ++c) {
            header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
            // OpenEXR's Slice takes a mutable pointer but only reads through it when writing.
            char* base = const_cast<char*>(reinterpret_cast<const char*>(image.values.data() + c));
            frame.insert(names[c], Imf::Slice(Imf::FLOAT, base, xStride, yStride));
        }
        Imf::OutputFile file(destination, header);
        file.setFrameBuffer(frame);
        file.writePixels(int(image.height));
    } catch (const std::exception& error) {
        std::string reason = error.what();
        std::replace(reason.begin(), reason.end(), '\n', ' ');
        throw ImageError("cannot write " + quoted(path) + ": " + reason);
    }
}

} // namespace

void writeExr(const std::filesystem::path& path, const FloatImage& image) {
    const std::string name = path.string();
    const char* file = name.c_str();
    writeExrTo(path, image, file);
}

std::string encodeExr(const FloatImage& image, const std::filesystem::path& name) {
    ExrMemoryOutput output(name.c_str());
    writeExrTo(name, image, output);
    return output.bytes();
}

} // namespace iblkit::image_io
