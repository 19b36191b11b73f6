#include "batch_progress.hpp"

#include "bake_command.hpp"

#include <fmt/core.h>

#include <unistd.h>

namespace iblkit::cli {

BatchProgress::BatchProgress(size_t bakes, bool quiet)
    : bakes_(bakes), quiet_(quiet), terminal_(isatty(STDERR_FILENO) != 0), started_(std::chrono::steady_clock::now()) {}

void BatchProgress::ended(const BatchResult& result, size_t line, const std::string& failure) {
    ++ended_;
    const char* clear = terminal_ ? "\r\033[K" : "";
    if (result.error || !failure.empty()) {
        fmt::print(stderr, "{}[{}/{}] {} (line {}): {}\n", clear, ended_, bakes_, result.name, line,
                   result.error ? result.error->what() : failure.c_str());
    } else if (!quiet_) {
        fmt::print(stderr, "{}[{}/{}] {}: baked in {:.2f} s\n", clear, ended_, bakes_, result.name, result.wallMilliseconds / 1e3);
    }
    if (result.summary) printPolicyReports(*result.summary, result.name + ": ");
    if (quiet_ || !terminal_ || ended_ == bakes_) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    fmt::print(stderr, "{} of {} left, about {:.0f} s", bakes_ - ended_, bakes_, elapsed / double(ended_) * double(bakes_ - ended_));
}

void printBatchCounts(const batch::BatchRecord& record, const std::filesystem::path& recordFile) {
    size_t baked = 0, done = 0, failed = 0, pending = 0;
    for (const auto& entry : record.bakes) {
        baked += entry.status == "baked";
        done += entry.status == "done";
        failed += entry.status == "failed";
        pending += entry.status == "pending";
    }
    fmt::print(stderr, "batch: {} baked, {} done already, {} failed, {} not baked ({})\n", baked, done, failed, pending,
               recordFile.string());
}

} // namespace iblkit::cli
