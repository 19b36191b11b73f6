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
// program is sent `killSignal` (SIGKILL unless given) if it still runs then; a program the
// signal ends has the exit code 128 + the signal's number.
ProcessResult runProcess(const std::vector<std::string>& command, const std::vector<std::string>& environment = {},
                         double killAfterSeconds = 0, int killSignal = 9);

} // namespace iblkit::testing
