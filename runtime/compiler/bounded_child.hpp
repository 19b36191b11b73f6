#pragma once

#include <functional>
#include <string>

namespace iblkit::compiler {

// What a child process may spend before it is stopped.
struct ChildLimits {
    unsigned cpuSeconds = 5;       // RLIMIT_CPU: preprocessing a real shader takes milliseconds
    unsigned wallSeconds = 20;     // then SIGKILL, for a child that waits instead of computing
    size_t extraMegabytes = 1024;  // address space beyond the parent's, RLIMIT_AS
};

// Runs `work` in a forked child under `limits` and returns what it returned. A CompileError
// the work throws is thrown again here with its message; a child stopped by a limit, a signal
// or a crash throws CompileError("<sourceName>: error: <what> <how it ended><hint>"). For work
// that only computes: the child shares no state back but the returned string.
std::string runInBoundedChild(const std::function<std::string()>& work, const ChildLimits& limits,
                              const std::string& sourceName, const std::string& what, const std::string& hint);

} // namespace iblkit::compiler
