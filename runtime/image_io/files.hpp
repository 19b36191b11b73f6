#pragma once

#include "texture.hpp"

#include <cstddef>
#include <filesystem>
#include <vector>

namespace iblkit::image_io {

// A whole file; ImageError "cannot open 'x': <reason>" when it cannot be read.
std::vector<std::byte> readFileBytes(const std::filesystem::path& path);
// A .ktx2 or .dds texture, by extension (case-insensitive); any other extension is an ImageError
// naming the supported ones.
Texture readTextureFile(const std::filesystem::path& path);

} // namespace iblkit::image_io
