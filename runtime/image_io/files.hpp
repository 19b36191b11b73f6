#pragma once

#include "texture.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <vector>

namespace iblkit::image_io {

// A whole regular file of at most `maxBytes` (a folder, a device or a pipe is refused, a pipe
// without waiting for a writer); ImageError "cannot open 'x': <reason>" when it cannot be read.
std::vector<std::byte> readFileBytes(const std::filesystem::path& path, uint64_t maxBytes = UINT64_MAX);
// The same a chunk at a time, for files too large to hold (hashing a bake's outputs).
void readFileInChunks(const std::filesystem::path& path, const std::function<void(std::span<const std::byte>)>& chunk);
// A .ktx2 or .dds texture, by extension (case-insensitive); any other extension is an ImageError
// naming the supported ones.
Texture readTextureFile(const std::filesystem::path& path);
// The same from the file's bytes, read once by the caller (who also hashes them).
Texture decodeTextureFile(std::span<const std::byte> bytes, const std::filesystem::path& path);

} // namespace iblkit::image_io
