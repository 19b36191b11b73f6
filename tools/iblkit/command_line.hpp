#pragma once

#include <string>
#include <vector>

namespace iblkit::cli {

// The compiler flags spelled as in cc and glslangValidator (-Os, -MD, -MF) are not
// single-letter options, which CLI11 cannot parse; they become --Os, --MD, --MF.
std::vector<std::string> normalizeArguments(int argc, char** argv);

// Splits "NAME=VALUE" (VALUE may be empty, and "NAME" alone gives "").
std::pair<std::string, std::string> splitAssignment(const std::string& text);

} // namespace iblkit::cli
