#include "bake_progress.hpp"

#include <fmt/core.h>

#include <fstream>
#include <string>

#include <unistd.h>

namespace iblkit::bake {

double peakResidentMebibytes() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.starts_with("VmHWM:")) return std::stod(line.substr(6)) / 1024; // in kB
    return 0;
}

BakeProgress::BakeProgress(bool quiet, std::FILE* stream)
    : quiet_(quiet), stream_(stream), terminal_(stream && ::isatty(::fileno(stream)) == 1) {}

void BakeProgress::begin(const std::string& step) {
    endPart();
    steps_.push_back({step, 0, 0, {}, 0});
    started_ = Clock::now();
    lastDetail_.clear();
    advance(0);
}

void BakeProgress::advance(double fraction, const std::string& detail) {
    lastDetail_ = detail;
    if (quiet_ || !terminal_) return;
    const auto now = Clock::now();
    if (fraction > 0 && now - lastShown_ < std::chrono::milliseconds(100)) return;
    lastShown_ = now;
    print(fraction, detail, "\r");
}

void BakeProgress::addDeviceTime(double milliseconds) {
    if (milliseconds <= 0) return;
    steps_.back().deviceMilliseconds += milliseconds;
    if (inPart_) steps_.back().parts.back().deviceMilliseconds += milliseconds;
}

void BakeProgress::part(const std::string& name) {
    endPart();
    steps_.back().parts.push_back({name, 0, 0});
    partStarted_ = Clock::now();
    inPart_ = true;
}

void BakeProgress::endPart() {
    if (!inPart_) return;
    steps_.back().parts.back().wallMilliseconds = std::chrono::duration<double, std::milli>(Clock::now() - partStarted_).count();
    inPart_ = false;
}

void BakeProgress::end() {
    endPart();
    steps_.back().wallMilliseconds = elapsedSeconds() * 1e3;
    steps_.back().peakMebibytes = peakResidentMebibytes();
    if (!quiet_) print(1, lastDetail_, "\n");
}

void BakeProgress::print(double fraction, const std::string& detail, const char* end) {
    // On a terminal the line is padded, so that a shorter one covers the longer before it.
    fmt::print(stream_, "{:<17} {:>3.0f}%  {:<20} {:6.2f} s{}", steps_.back().name, fraction * 100, detail, elapsedSeconds(),
               terminal_ ? std::string(8, ' ') + end : std::string(end));
    std::fflush(stream_);
}

double BakeProgress::elapsedSeconds() const {
    return std::chrono::duration<double>(Clock::now() - started_).count();
}

} // namespace iblkit::bake
