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
// this process's, and collects its exit code and output. With killAfterSeconds > 0 the
// program is killed (SIGKILL) if it still runs then; its exit code is then 128 + 9.
ProcessResult runProcess(const std::vector<std::string>& command, const std::vector<std::string>& environment = {},
                         double killAfterSeconds = 0);

} // namespace iblkit::testing
