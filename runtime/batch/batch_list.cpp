#include "batch_list.hpp"

#include "batch_error.hpp"

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace iblkit::batch {

std::vector<std::string> splitWords(std::string_view line) {
    std::vector<std::string> words;
    std::string word;
    bool inWord = false;
    for (size_t at = 0; at < line.size(); ++at) {
        const char c = line[at];
        if (c == ' ' || c == '\t' || c == '\r') {
            if (inWord) words.push_back(std::move(word));
            word.clear();
            inWord = false;
        } else if (c == '#' && !inWord) {
            break;
        } else if (c == '\'' || c == '"') {
            const size_t end = line.find(c, at + 1);
            if (end == std::string_view::npos) throw std::invalid_argument(fmt::format("the quote {} is not closed", c));
            word += line.substr(at + 1, end - at - 1);
            inWord = true;
            at = end;
        } else if (c == '\\') {
            if (at + 1 == line.size()) throw std::invalid_argument("a backslash ends the line");
            word += line[++at];
            inWord = true;
        } else {
            word += c;
            inWord = true;
        }
    }
    if (inWord) words.push_back(std::move(word));
    return words;
}

bool isFolderName(std::string_view name) {
    if (name.empty() || name.front() == '.' || name.size() > 200) return false;
    return name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._-") ==
           std::string_view::npos;
}

std::vector<BatchLine> parseBatchList(std::string_view text, const std::string& listName) {
    std::vector<BatchLine> lines;
    std::map<std::string, size_t> named;
    size_t number = 0;
    for (size_t start = 0; start < text.size();) {
        const size_t end = std::min(text.find('\n', start), text.size());
        const auto line = text.substr(start, end - start);
        start = end + 1;
        ++number;
        const auto where = fmt::format("{}:{}", listName, number);
        std::vector<std::string> words;
        try {
            words = splitWords(line);
        } catch (const std::invalid_argument& error) {
            throw BatchError(fmt::format("{}: error: {}", where, error.what()));
        }
        if (words.empty()) continue;
        if (!isFolderName(words.front()))
            throw BatchError(fmt::format("{}: error: '{}' is not a folder name (letters, digits, '.', '_' and '-', not "
                                         "starting with '.')", where, words.front()));
        if (words.front() == "batch.json" || words.front() == "batch-shards")
            throw BatchError(fmt::format("{}: error: '{}' is the batch's own record's name", where, words.front()));
        if (const auto [earlier, fresh] = named.emplace(words.front(), number); !fresh)
            throw BatchError(fmt::format("{}: error: '{}' is named on line {} already", where, words.front(), earlier->second));
        lines.push_back({number, words.front(), std::vector<std::string>(words.begin() + 1, words.end())});
    }
    if (lines.empty()) throw BatchError(listName + ": error: the list names no bake");
    return lines;
}

std::vector<BatchLine> readBatchList(const std::filesystem::path& list) {
    std::error_code error;
    if (std::filesystem::is_directory(list, error)) throw BatchError(list.string() + ": error: a folder, not a list");
    std::ifstream in(list, std::ios::binary);
    if (!in) throw BatchError(list.string() + ": error: cannot read the list");
    std::string text;
    char chunk[1 << 16];
    while (text.size() <= kMaxListBytes && in.read(chunk, sizeof chunk).gcount() > 0) text.append(chunk, size_t(in.gcount()));
    if (text.size() > kMaxListBytes)
        throw BatchError(fmt::format("{}: error: the list is larger than {} MiB", list.string(), kMaxListBytes >> 20));
    if (text.find('\0') != std::string::npos) throw BatchError(list.string() + ": error: not a text file (it holds a NUL byte)");
    if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3); // a UTF-8 byte-order mark, as editors on Windows write
    return parseBatchList(text, list.string());
}

} // namespace iblkit::batch
