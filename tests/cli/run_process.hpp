#pragma once

#include <string>
#include <vector>

namespace iblkit::testing {

struct ProcessResult {
    int exitCode;
    std::string out;
    std::string err;
};

// Runs a program with its arguments (no shell), with `environment` ("NAME=value") added to
// this process's, and collects its exit code and output.
ProcessResult runProcess(const std::vector<std::string>& command, const std::vector<std::string>& environment = {});

} // namespace iblkit::testing
