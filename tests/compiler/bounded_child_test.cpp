// runInBoundedChild: what the child returns or throws comes back, and however it ends otherwise
// is one CompileError that says how.
#include "bounded_child.hpp"
#include "compile_error.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <unistd.h>

namespace iblkit::compiler {
namespace {

std::string messageOf(const std::function<std::string()>& work, const ChildLimits& limits = {}) {
    try {
        runInBoundedChild(work, limits, "a.hlsl", "preprocessing", "");
    } catch (const CompileError& error) {
        return error.what();
    }
    return "(no error)";
}

TEST(BoundedChild, ReturnsWhatTheWorkReturned) {
    EXPECT_EQ(runInBoundedChild([] { return std::string("result\0bytes", 12); }, {}, "a.hlsl", "preprocessing", ""),
              std::string("result\0bytes", 12));
}

TEST(BoundedChild, ThrowsTheWorksCompileErrorAgain) {
    EXPECT_EQ(messageOf([]() -> std::string { throw CompileError("a.hlsl:3:1: error: no"); }), "a.hlsl:3:1: error: no");
}

void exitQuietly(int) { _exit(0); }

// Sanitizers and fuzzers install a SIGSEGV handler that the child inherits; before the child
// restored the default, this crash ended through the handler and read as "ended without a result".
TEST(BoundedChild, ACrashIsReportedByItsSignalWhateverHandlerTheParentHas) {
    struct sigaction quiet {}, previous{};
    quiet.sa_handler = exitQuietly;
    sigaction(SIGSEGV, &quiet, &previous);
    const auto message = messageOf([]() -> std::string {
        std::raise(SIGSEGV);
        return "survived";
    });
    sigaction(SIGSEGV, &previous, nullptr);
    EXPECT_EQ(message, "a.hlsl: error: preprocessing crashed (Segmentation fault)");
}

TEST(BoundedChild, WorkBeyondItsCpuLimitIsStopped) {
    ChildLimits limits;
    limits.cpuSeconds = 1;
    const auto message = messageOf([]() -> std::string {
        volatile unsigned long spins = 0;
        for (;;) {
            spins = spins + 1;
        }
    }, limits);
    EXPECT_EQ(message, "a.hlsl: error: preprocessing used more than 1 s of CPU time");
}

TEST(BoundedChild, WorkThatWaitsIsStoppedAtItsWallLimit) {
    ChildLimits limits;
    limits.wallSeconds = 1;
    const auto message = messageOf([]() -> std::string {
        pause();
        return "";
    }, limits);
    EXPECT_EQ(message, "a.hlsl: error: preprocessing did not finish within 1 s");
}

} // namespace
} // namespace iblkit::compiler
