#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace iblkit::cache {

// SHA-256 (OpenSSL's) as 64 lower-case hex digits.
std::string sha256Hex(std::span<const std::byte> bytes);
std::string sha256Hex(std::string_view text);
std::string sha256Hex(std::span<const std::string_view> parts); // of the parts one after another
std::string sha256OfFile(const std::filesystem::path& path); // image_io::ImageError when unreadable or not a regular file

// What tells this build of the running program from every other, taken once: the digest of the
// GNU build id its linker wrote (a hash of the whole program), else of its file. A cache key that
// holds it changes with any rebuild — host code, built-in shaders, statically linked libraries.
const std::string& programDigest();

} // namespace iblkit::cache
