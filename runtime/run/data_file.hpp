#pragma once

#include "texel_format.hpp"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::run {

// Values read from a data file: a .npy array (float16/32/64, int32, uint32 or uint8, any
// shape, C order), or raw little-endian data in the resource's own format. Throws RunError
// when the file is missing or malformed, or (with expectedCount) holds another count of values.
std::vector<double> readValues(const std::filesystem::path& path, const vulkan::TexelFormat& format);
std::vector<double> readValues(const std::filesystem::path& path, const vulkan::TexelFormat& format, size_t expectedCount);

// The bytes of a data file: .npy with the given shape, uint32 or int32 for an integer format and
// float32 for the others; anything else, raw data in the resource's format.
std::string encodeValues(const std::filesystem::path& path, const vulkan::TexelFormat& format,
                         const std::vector<double>& values, const std::vector<size_t>& shape);

} // namespace iblkit::run
