#pragma once

#include <exception>
#include <filesystem>
#include <string>

namespace iblkit::files {

// nlohmann's exception in the kit's words, without its "[json.exception.parse_error.101]" code:
// "not valid JSON at line 2, column 1: syntax error ...", "expected a number, found a string",
// "\"shaders\" is missing", "element 3 is missing". For one-line messages that name the file.
std::string jsonErrorInWords(const std::exception& error); // a nlohmann::json::exception

// std::filesystem's "filesystem error: cannot create directories: Not a directory [a/b]" as
// "cannot create directories 'a/b': Not a directory".
std::string filesystemErrorInWords(const std::filesystem::filesystem_error& error);

} // namespace iblkit::files
