#include "json_words.hpp"

#include <regex>

namespace iblkit::files {

std::string jsonErrorInWords(const std::exception& error) {
    std::string text = error.what();
    if (const auto code = text.find("] "); text.starts_with("[json.exception.") && code != std::string::npos)
        text.erase(0, code + 2);
    static const std::regex parse("^parse error at (line \\d+, column \\d+): (.*)$"),
        parseAtByte("^parse error( at byte \\d+)?: (.*)$"), type("^type must be (\\w+), but is (\\w+)$"),
        key("^key '(.*)' not found$"), index("^array index (\\d+) is out of range$");
    std::smatch match;
    if (std::regex_match(text, match, parse)) return "not valid JSON at " + match[1].str() + ": " + match[2].str();
    if (std::regex_match(text, match, parseAtByte)) return "not valid JSON: " + match[2].str();
    const auto article = [](const std::string& word) { return (word == "array" || word == "object" ? "an " : "a ") + word; };
    if (std::regex_match(text, match, type))
        return "expected " + article(match[1].str()) + ", found " + (match[2] == "null" ? std::string("null") : article(match[2].str()));
    if (std::regex_match(text, match, key)) return "\"" + match[1].str() + "\" is missing";
    if (std::regex_match(text, match, index)) return "element " + match[1].str() + " is missing";
    return text;
}

} // namespace iblkit::files
