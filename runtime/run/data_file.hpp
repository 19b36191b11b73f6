#pragma once

#include "texel_format.hpp"

#include <cstddef>
#include <filesystem>
#include <vector>

namespace iblkit::run {

// Values read from a data file: a .npy array (float16/32, int32, uint32 or uint8, any
// shape, C order), or raw little-endian data in the resource's own format. Throws
// RunError when the file is missing, malformed, or holds another count of values.
std::vector<float> readValues(const std::filesystem::path& path, const vulkan::TexelFormat& format, size_t expectedCount);

// .npy: float32 with the given shape; anything else: raw bytes in the resource's format.
// Written all or nothing.
void writeValues(const std::filesystem::path& path, const vulkan::TexelFormat& format, const std::vector<float>& values,
                 const std::vector<size_t>& shape);

} // namespace iblkit::run
