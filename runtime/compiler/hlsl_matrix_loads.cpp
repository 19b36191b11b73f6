#include "hlsl_matrix_loads.hpp"

#include <regex>
#include <vector>

namespace iblkit::compiler {
namespace {

// The index of the ')' that closes the '(' at `open`, or npos.
size_t closingParenthesis(const std::string& text, size_t open) {
    int depth = 0;
    for (size_t i = open; i < text.size(); ++i) {
        if (text[i] == '(') ++depth;
        if (text[i] == ')' && --depth == 0) return i;
    }
    return std::string::npos;
}

std::vector<std::string> topLevelArguments(const std::string& list) {
    std::vector<std::string> arguments;
    int depth = 0;
    size_t begin = 0;
    for (size_t i = 0; i < list.size(); ++i) {
        if (list[i] == '(') ++depth;
        if (list[i] == ')') --depth;
        if (list[i] == ',' && depth == 0) {
            arguments.push_back(list.substr(begin, i - begin));
            begin = i + 1;
        }
    }
    arguments.push_back(list.substr(begin));
    return arguments;
}

} // namespace

std::string withFloatMatrixLoads(std::string source) {
    static const std::regex cast(R"(\basfloat\(u?int([1-4]x[1-4])\()");
    std::smatch match;
    size_t from = 0;
    while (std::regex_search(source.cbegin() + static_cast<std::ptrdiff_t>(from), source.cend(), match, cast)) {
        const size_t at = from + static_cast<size_t>(match.position(0));
        const size_t innerOpen = at + static_cast<size_t>(match.length(0)) - 1;
        const size_t innerClose = closingParenthesis(source, innerOpen);
        if (innerClose == std::string::npos || innerClose + 1 >= source.size() || source[innerClose + 1] != ')') {
            from = innerClose == std::string::npos ? source.size() : innerOpen + 1;
            continue;
        }
        std::string rewritten = "float" + match[1].str() + "(";
        const auto arguments = topLevelArguments(source.substr(innerOpen + 1, innerClose - innerOpen - 1));
        for (size_t i = 0; i < arguments.size(); ++i) {
            const size_t first = arguments[i].find_first_not_of(' ');
            rewritten += (i ? ", " : "") + std::string("asfloat(") + arguments[i].substr(first) + ")";
        }
        rewritten += ")";
        source.replace(at, innerClose + 2 - at, rewritten);
        from = at + rewritten.size();
    }
    return source;
}

} // namespace iblkit::compiler
