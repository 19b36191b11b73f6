#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace iblkit::image_io {

// Where a Radiance RGBE file's pixels are, found the way stb_image parses the header: the
// signature line, lines up to an empty one (with FORMAT=32-bit_rle_rgbe among them), then the
// resolution line "-Y height +X width".
struct RadianceLayout {
    uint32_t width = 0, height = 0;
    size_t dataStart = 0;
};

// Throws ImageError "'<name>' ..." for a header stb_image would not read or a size the kit does not.
RadianceLayout readRadianceLayout(std::span<const std::byte> bytes, const std::string& name);

// Walks the pixel data as stb_image decodes it (flat, or run-length encoded scanlines) without
// decoding it. stb_image reads zeros past the end of its input and loops forever on a zero run
// length, so a truncated or corrupt file must be refused before it gets there: throws ImageError.
void requireCompletePixelData(std::span<const std::byte> bytes, const RadianceLayout& layout, const std::string& name);

} // namespace iblkit::image_io
