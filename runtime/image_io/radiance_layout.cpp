#include "radiance_layout.hpp"

#include "image_error.hpp"

#include <cstdlib>
#include <optional>
#include <string_view>

namespace iblkit::image_io {
namespace {

constexpr uint64_t kMaxTexels = uint64_t(1) << 28; // as for EXR: a 16384x8192 panorama fits
constexpr uint32_t kMaxSide = 65536;

[[noreturn]] void fail(const std::string& name, const std::string& problem) {
    throw ImageError("'" + name + "' " + problem);
}

// The line starting at `at`, without its '\n'; nullopt when the file ends first.
std::optional<std::string_view> lineAt(std::span<const std::byte> bytes, size_t at) {
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const size_t end = text.find('\n', at);
    if (end == std::string_view::npos) return std::nullopt;
    return text.substr(at, end - at);
}

// "-Y <height> +X <width>", parsed as stb_image parses it (strtol after each axis).
bool parseResolution(std::string_view line, long& height, long& width) {
    const std::string text(line);
    if (text.compare(0, 3, "-Y ") != 0) return false;
    char* next = nullptr;
    height = std::strtol(text.c_str() + 3, &next, 10);
    while (*next == ' ') ++next;
    if (std::string_view(next).substr(0, 3) != "+X ") return false;
    width = std::strtol(next + 3, nullptr, 10);
    return true;
}

class PixelWalk {
public:
    PixelWalk(std::span<const std::byte> data, const RadianceLayout& layout, const std::string& name, size_t fileSize)
        : data_(data), layout_(layout), name_(name), fileSize_(fileSize) {}

    void run() {
        const uint64_t flatBytes = uint64_t(layout_.width) * layout_.height * 4;
        // stb_image reads widths outside [8, 32768) flat, 4 bytes a pixel.
        if (layout_.width < 8 || layout_.width >= 32768) return require(flatBytes);
        for (uint32_t row = 0; row < layout_.height; ++row) {
            require(4);
            const uint8_t c1 = byte(0), c2 = byte(1), high = byte(2), low = byte(3);
            // A scanline not starting 2, 2 makes stb_image read the whole image flat from here.
            if (c1 != 2 || c2 != 2 || (high & 0x80)) return require(flatBytes);
            if (((uint32_t(high) << 8) | low) != layout_.width) corrupt(row, "its length is not the image width");
            at_ += 4;
            for (int component = 0; component < 4; ++component) walkComponent(row);
        }
    }

private:
    void walkComponent(uint32_t row) {
        for (uint32_t filled = 0; filled < layout_.width;) {
            require(1);
            const uint8_t count = byte(0);
            const bool run = count > 128;
            const uint32_t length = run ? count - 128u : count;
            if (length == 0 || length > layout_.width - filled) corrupt(row, "a run length overflows the scanline or is 0");
            require(run ? 2 : 1 + size_t(length));
            at_ += run ? 2 : 1 + size_t(length);
            filled += length;
        }
    }
    uint8_t byte(size_t offset) const { return uint8_t(data_[at_ + offset]); }
    void require(uint64_t count) const {
        if (data_.size() - at_ < count)
            fail(name_, "is truncated: its " + std::to_string(layout_.width) + "x" + std::to_string(layout_.height) +
                            " pixels need more than the file's " + std::to_string(fileSize_) + " bytes");
    }
    [[noreturn]] void corrupt(uint32_t row, const std::string& why) const {
        fail(name_, "has a corrupt run-length encoded scanline (row " + std::to_string(row) + "): " + why);
    }

    std::span<const std::byte> data_;
    const RadianceLayout& layout_;
    const std::string& name_;
    size_t fileSize_;
    size_t at_ = 0;
};

} // namespace

RadianceLayout readRadianceLayout(std::span<const std::byte> bytes, const std::string& name) {
    const auto signature = lineAt(bytes, 0);
    if (!signature || (*signature != "#?RADIANCE" && *signature != "#?RGBE"))
        fail(name, "is not a Radiance HDR image: its first line is not #?RADIANCE or #?RGBE");
    size_t at = signature->size() + 1;
    bool rgbe = false;
    for (auto line = lineAt(bytes, at);; line = lineAt(bytes, at)) {
        if (!line) fail(name, "is truncated: its header has no end");
        at += line->size() + 1;
        if (line->empty()) break;
        rgbe = rgbe || *line == "FORMAT=32-bit_rle_rgbe";
    }
    if (!rgbe) fail(name, "is not an RGBE Radiance image: its header has no FORMAT=32-bit_rle_rgbe line");
    const auto resolution = lineAt(bytes, at);
    if (!resolution) fail(name, "is truncated: it ends in its resolution line");
    long height = 0, width = 0;
    if (!parseResolution(*resolution, height, width))
        fail(name, "has the resolution line '" + std::string(*resolution) +
                       "'; supported: -Y <height> +X <width> (rows top first)");
    if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide || uint64_t(width) * uint64_t(height) > kMaxTexels)
        fail(name, "is " + std::to_string(width) + "x" + std::to_string(height) +
                       "; supported: 1 to 65536 on a side, 2^28 texels in all");
    return {uint32_t(width), uint32_t(height), at + resolution->size() + 1};
}

void requireCompletePixelData(std::span<const std::byte> bytes, const RadianceLayout& layout, const std::string& name) {
    PixelWalk(bytes.subspan(layout.dataStart), layout, name, bytes.size()).run();
}

} // namespace iblkit::image_io
