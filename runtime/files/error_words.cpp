#include "error_words.hpp"

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

std::string filesystemErrorInWords(const std::filesystem::filesystem_error& error) {
    std::string text = error.what();
    const std::string prefix = "filesystem error: ";
    if (text.starts_with(prefix)) text.erase(0, prefix.size());
    if (const auto bracket = text.find(" ["); bracket != std::string::npos) text.erase(bracket);
    const std::string reason = error.code().message();
    if (text.ends_with(": " + reason)) text.erase(text.size() - reason.size() - 2);
    std::string paths;
    for (const auto* path : {&error.path1(), &error.path2()})
        if (!path->empty()) paths += (paths.empty() ? " '" : " and '") + path->string() + "'";
    return text + paths + ": " + reason;
}

} // namespace iblkit::files
