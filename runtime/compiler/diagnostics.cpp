#include "diagnostics.hpp"

#include "include_resolver.hpp"

#include <regex>
#include <sstream>

namespace iblkit::compiler {
namespace {

std::string lineOf(const std::string& text, int number) {
    std::istringstream lines(text);
    std::string line;
    for (int current = 1; std::getline(lines, line); ++current)
        if (current == number) return line;
    return {};
}

int columnOfToken(const IncludeResolver& files, const std::string& file, int line, const std::string& message) {
    std::smatch token;
    if (!std::regex_search(message, token, std::regex(R"('([^']+)')"))) return 1;
    const std::string* text = files.sourceText(file);
    if (!text) return 1;
    const auto at = lineOf(*text, line).find(token[1].str());
    return at == std::string::npos ? 1 : static_cast<int>(at) + 1;
}

std::string includeChain(const IncludeResolver& files, const std::string& file) {
    std::string chain;
    for (const IncludeSite* site = files.includeSite(file); site; site = files.includeSite(site->includer))
        chain = "In file included from " + site->includer + ":" + std::to_string(site->line) + ":\n" + chain;
    return chain;
}

bool isNoise(const std::string& message) {
    return message.find("compilation errors.") != std::string::npos ||
           message.find("compilation terminated") != std::string::npos;
}

} // namespace

Diagnostics parseGlslangLog(const std::string& log, const IncludeResolver& files, const std::string& sourceName) {
    static const std::regex located(R"(^(ERROR|WARNING): (.+?):(\d+): (.*)$)");
    static const std::regex unlocated(R"(^(ERROR|WARNING): (.*)$)");
    Diagnostics diagnostics;
    std::istringstream lines(log);
    std::string line;
    while (std::getline(lines, line)) {
        std::smatch match;
        std::string formatted;
        bool isError = false;
        if (std::regex_match(line, match, located) && !isNoise(match[4])) {
            const std::string file = match[2];
            const int lineNumber = std::stoi(match[3]);
            std::string message = match[4];
            message.erase(message.find_last_not_of(' ') + 1);
            isError = match[1] == "ERROR";
            formatted = includeChain(files, file) + file + ":" + std::to_string(lineNumber) + ":" +
                        std::to_string(columnOfToken(files, file, lineNumber, message)) + ": " +
                        (isError ? "error: " : "warning: ") + message;
        } else if (std::regex_match(line, match, unlocated) && !isNoise(match[2])) {
            isError = match[1] == "ERROR";
            formatted = sourceName + ": " + (isError ? "error: " : "warning: ") + std::string(match[2]);
        } else {
            continue;
        }
        (isError ? diagnostics.errors : diagnostics.warnings).push_back(formatted);
    }
    return diagnostics;
}

} // namespace iblkit::compiler
