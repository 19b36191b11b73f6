#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace iblkit::image_io {

// 'path', as every message names a file.
inline std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

inline std::string lowerExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

// "'.png'" or "(no extension)", for "unsupported ... format" messages.
inline std::string describedExtension(const std::filesystem::path& path) {
    const auto extension = path.extension().string();
    return extension.empty() ? "(no extension)" : "'" + extension + "'";
}

} // namespace iblkit::image_io
