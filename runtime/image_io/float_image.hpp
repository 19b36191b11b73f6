#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace iblkit::image_io {

// An HDR image in memory, as environments arrive and EXR outputs leave.
struct FloatImage {
    uint32_t width = 0, height = 0, channels = 0; // channels: 3 (RGB) or 4 (RGBA)
    std::vector<float> values;                    // rows top first, channels interleaved
};

// Radiance RGBE (.hdr) through stb_image; 3 channels. Files whose first line is not #?RADIANCE or
// #?RGBE are refused rather than converted from 8 bits, and truncated or corrupt pixel data is
// refused before stb_image sees it (it would read black past the end, or loop forever).
FloatImage readRadianceHdr(const std::filesystem::path& path);
// The same from bytes in memory; `name` names them in messages.
FloatImage decodeRadianceHdr(std::span<const std::byte> bytes, const std::filesystem::path& name);
// OpenEXR through Imf::InputFile with a 32-bit float frame buffer, so half, float and uint
// channels and every compression read without loss; R, G, B and A (1 where absent) over the data
// window. Luminance/chroma files (Y, RY, BY) go through Imf::RgbaInputFile instead. 4 channels.
FloatImage readExr(const std::filesystem::path& path);
FloatImage decodeExr(std::span<const std::byte> bytes, const std::filesystem::path& name);
// By extension, case-insensitive: .hdr/.pic -> readRadianceHdr, .exr -> readExr.
FloatImage readFloatImage(const std::filesystem::path& path);
// The same from the file's bytes, read once by the caller (who also hashes them).
FloatImage decodeFloatImage(std::span<const std::byte> bytes, const std::filesystem::path& path);

// The image's texels as RGBA (alpha 1 where the image has none), rows top first.
std::vector<float> rgbaValues(const FloatImage& image);

// 32-bit FLOAT channels R, G, B (and A when channels is 4), ZIP compression.
void writeExr(const std::filesystem::path& path, const FloatImage& image);
// The same EXR, in memory; `name` names it in messages.
std::string encodeExr(const FloatImage& image, const std::filesystem::path& name);
// 8-bit RGBA, rows top first, through stb_image_write.
void writePng(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const uint8_t> rgba8);
// The same PNG, in memory.
std::string encodePng(uint32_t width, uint32_t height, std::span<const uint8_t> rgba8);

// Every function throws ImageError, one line naming the file and the problem.

} // namespace iblkit::image_io
