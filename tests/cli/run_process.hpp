#pragma once

#include <string>
#include <vector>

namespace iblkit::testing {

struct ProcessResult {
    int exitCode;
    std::string out;
    std::string err;
};

// Runs a program with its arguments (no shell) and collects its exit code and output.
ProcessResult runProcess(const std::vector<std::string>& command);

} // namespace iblkit::testing
