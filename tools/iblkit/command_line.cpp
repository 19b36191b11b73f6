#include "command_line.hpp"

#include <algorithm>
#include <array>

namespace iblkit::cli {

std::vector<std::string> normalizeArguments(int argc, char** argv) {
    constexpr std::array kCompilerStyle{"-Os", "-MD", "-MF", "-HV", "-enable-16bit-types"};
    std::vector<std::string> arguments;
    for (int i = 1; i < argc; ++i) {
        std::string argument = argv[i];
        if (std::find(kCompilerStyle.begin(), kCompilerStyle.end(), argument) != kCompilerStyle.end())
            argument = "-" + argument;
        arguments.push_back(std::move(argument));
    }
    std::reverse(arguments.begin(), arguments.end()); // CLI11 parses a reversed vector
    return arguments;
}

std::pair<std::string, std::string> splitAssignment(const std::string& text) {
    const auto at = text.find('=');
    if (at == std::string::npos) return {text, ""};
    return {text.substr(0, at), text.substr(at + 1)};
}

} // namespace iblkit::cli
