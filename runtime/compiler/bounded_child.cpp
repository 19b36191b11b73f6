#include "bounded_child.hpp"

#include "compile_error.hpp"

#include <chrono>
#include <csignal>
#include <cstring>
#include <fstream>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace iblkit::compiler {
namespace {

constexpr char kResult = 'R', kError = 'E';

size_t addressSpaceBytes() {
    std::ifstream statm("/proc/self/statm");
    size_t pages = 0;
    statm >> pages;
    return pages * size_t(sysconf(_SC_PAGESIZE));
}

void writeAll(int fd, const std::string& bytes) {
    for (size_t done = 0; done < bytes.size();) {
        const auto written = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (written <= 0) return;
        done += size_t(written);
    }
}

// The child dies of a crash's signal itself, not through a handler it inherited (a sanitizer's or
// a fuzzer's would report glslang's crash as the parent's and write its own files).
void restoreDefaultCrashHandlers() {
    for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(signal, SIG_DFL);
}

[[noreturn]] void runChild(int fd, const std::function<std::string()>& work, const ChildLimits& limits,
                           size_t addressSpace) {
    restoreDefaultCrashHandlers();
    const rlimit cpu{limits.cpuSeconds, limits.cpuSeconds + 2}; // SIGXCPU at the soft limit, SIGKILL only later
    setrlimit(RLIMIT_CPU, &cpu);
    const rlim_t bytes = addressSpace + limits.extraMegabytes * (size_t(1) << 20);
    const rlimit memory{bytes, bytes};
    setrlimit(RLIMIT_AS, &memory);
    std::string message;
    try {
        message = kResult + work();
    } catch (const CompileError& error) {
        message = kError + std::string(error.what());
    } catch (const std::bad_alloc&) {
        _exit(3);
    } catch (const std::exception& error) { // not the compiler's own words, but never an abort read as memory
        message = kError + std::string("error: internal error: ") + error.what();
    }
    writeAll(fd, message);
    _exit(0);
}

// Everything the child writes, until it closes the pipe or the deadline passes.
std::string readUntil(int fd, std::chrono::steady_clock::time_point deadline, bool& timedOut) {
    std::string bytes;
    char buffer[65536];
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) { timedOut = true; return bytes; }
        pollfd descriptor{fd, POLLIN, 0};
        if (poll(&descriptor, 1, int(left.count())) <= 0) continue;
        const auto got = ::read(fd, buffer, sizeof buffer);
        if (got <= 0) return bytes;
        bytes.append(buffer, size_t(got));
    }
}

std::string howItEnded(int status, bool timedOut, const ChildLimits& limits) {
    if (timedOut) return "did not finish within " + std::to_string(limits.wallSeconds) + " s";
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU)
        return "used more than " + std::to_string(limits.cpuSeconds) + " s of CPU time";
    if ((WIFEXITED(status) && WEXITSTATUS(status) == 3) || (WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT))
        return "needed more than " + std::to_string(limits.extraMegabytes) + " MiB of memory";
    if (WIFSIGNALED(status)) return std::string("crashed (") + strsignal(WTERMSIG(status)) + ")";
    return "ended without a result";
}

} // namespace

std::string runInBoundedChild(const std::function<std::string()>& work, const ChildLimits& limits,
                              const std::string& sourceName, const std::string& what, const std::string& hint) {
    int fds[2];
    if (pipe(fds) != 0) throw CompileError(sourceName + ": error: cannot make a pipe: " + std::strerror(errno));
    const size_t addressSpace = addressSpaceBytes();
    const pid_t child = fork();
    if (child < 0) {
        close(fds[0]);
        close(fds[1]);
        throw CompileError(sourceName + ": error: cannot start a process: " + std::strerror(errno));
    }
    if (child == 0) {
        close(fds[0]);
        runChild(fds[1], work, limits, addressSpace);
    }
    close(fds[1]);
    bool timedOut = false;
    const auto bytes = readUntil(fds[0], std::chrono::steady_clock::now() + std::chrono::seconds(limits.wallSeconds),
                                 timedOut);
    close(fds[0]);
    if (timedOut) kill(child, SIGKILL);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {}
    const bool finished = !timedOut && WIFEXITED(status) && WEXITSTATUS(status) == 0 && !bytes.empty();
    if (finished && bytes[0] == kResult) return bytes.substr(1);
    if (finished && bytes[0] == kError) throw CompileError(bytes.substr(1));
    throw CompileError(sourceName + ": error: " + what + " " + howItEnded(status, timedOut, limits) + hint);
}

} // namespace iblkit::compiler
