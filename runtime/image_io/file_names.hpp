#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace iblkit::image_io {

// 'path', as every message names a file.
inline std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

// A path as JSON (always UTF-8) can hold it: valid UTF-8 kept, every other byte written as
// "\xNN" (file names on Linux are bytes, and JSON writers refuse what is not UTF-8).
inline std::string utf8Name(const std::filesystem::path& path) {
    const std::string bytes = path.string();
    std::string text;
    constexpr char kHex[] = "0123456789abcdef";
    for (size_t i = 0; i < bytes.size();) {
        const auto lead = static_cast<unsigned char>(bytes[i]);
        const size_t length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
        bool valid = length > 0 && i + length <= bytes.size() && (length == 1 || lead >= 0xC2) && lead <= 0xF4;
        for (size_t k = 1; valid && k < length; ++k) valid = (static_cast<unsigned char>(bytes[i + k]) >> 6) == 0x2;
        if (valid && length > 2) { // no overlong forms, surrogates or code points past U+10FFFF
            const auto second = static_cast<unsigned char>(bytes[i + 1]);
            valid = !(lead == 0xE0 && second < 0xA0) && !(lead == 0xED && second > 0x9F) &&
                    !(lead == 0xF0 && second < 0x90) && !(lead == 0xF4 && second > 0x8F);
        }
        if (valid) {
            text.append(bytes, i, length);
            i += length;
        } else {
            text += std::string("\\x") + kHex[lead >> 4] + kHex[lead & 15];
            ++i;
        }
    }
    return text;
}

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
