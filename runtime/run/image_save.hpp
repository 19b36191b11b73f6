#pragma once

#include "texel_format.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::run {

// Whether a save's file name asks for an image people look at (.png, .exr) rather than data.
bool isPictureFile(const std::filesystem::path& path);

// One 2D image as a picture. EXR: the float values as they are (one channel as grey, two as red
// and green). PNG: 8-bit RGBA; float values through the sRGB curve clamped to [0, 1], UNORM ones
// as stored. Throws RunError for an integer format, or for more than one layer or mip.
std::string encodePicture(const std::filesystem::path& path, const vulkan::TexelFormat& format, const std::vector<double>& values,
                          uint32_t width, uint32_t height, uint32_t layers, uint32_t mips);

} // namespace iblkit::run
