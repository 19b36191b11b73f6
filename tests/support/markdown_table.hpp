#pragma once
// The cells of a Markdown table row, for tests that read a generated report.
#include <string>
#include <vector>

namespace iblkit::testing {

// "| a | b |  |" -> {"a", "b", ""}: the text between the bars, trimmed. Empty for a line that is
// not a table row.
inline std::vector<std::string> tableCells(const std::string& line) {
    std::vector<std::string> cells;
    if (!line.starts_with("|") || !line.ends_with("|")) return cells;
    for (size_t at = 1, bar; (bar = line.find('|', at)) != std::string::npos; at = bar + 1) {
        const auto first = line.find_first_not_of(' ', at);
        const auto last = line.find_last_not_of(' ', bar - 1);
        cells.push_back(first < bar && last >= first ? line.substr(first, last - first + 1) : "");
    }
    return cells;
}

} // namespace iblkit::testing
