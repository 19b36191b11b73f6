#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace iblkit::batch {

// One line of a batch list: `NAME [ENV] [bake flags]`, split into words as a shell would split
// them (whitespace; '...' and "..." quote; a backslash escapes the next character), without any
// expansion. `#` at the start of a word starts a comment.
struct BatchLine {
    size_t number = 0;  // in the file, from 1
    std::string name;   // DIR/NAME is its folder
    std::vector<std::string> arguments; // what follows the name, as `iblkit bake` would take them
};

// The lists a batch reads are at most this large: a list of a million lines is about 60 MB.
inline constexpr size_t kMaxListBytes = 64u << 20;

// Every line of the list that is not blank or a comment. Throws BatchError naming the file and the
// line: an unreadable or oversized file, an unterminated quote, a name that is not a folder name
// (letters, digits, '.', '_' and '-', not starting with '.'), a name given twice.
std::vector<BatchLine> readBatchList(const std::filesystem::path& list);
std::vector<BatchLine> parseBatchList(std::string_view text, const std::string& listName);

// The words of one line (throws std::invalid_argument for an unterminated quote or escape).
std::vector<std::string> splitWords(std::string_view line);

bool isFolderName(std::string_view name);

} // namespace iblkit::batch
