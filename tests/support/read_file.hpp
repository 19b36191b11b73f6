#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace iblkit::testing {

// A file's whole contents, or "" when it cannot be read.
inline std::string readFile(const std::filesystem::path& path) {
    std::ifstream stream(path, std::ios::binary);
    std::ostringstream text;
    text << stream.rdbuf();
    return text.str();
}

} // namespace iblkit::testing
