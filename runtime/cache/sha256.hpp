#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

namespace iblkit::cache {

// SHA-256 (OpenSSL's) as 64 lower-case hex digits.
std::string sha256Hex(std::span<const std::byte> bytes);
std::string sha256OfFile(const std::filesystem::path& path); // image_io::ImageError when unreadable or not a regular file

} // namespace iblkit::cache
