#include "bake_progress.hpp"

#include <fmt/core.h>

namespace iblkit::bake {

void BakeProgress::begin(const std::string& step) {
    steps_.push_back({step, 0, 0});
    started_ = Clock::now();
    advance(0);
}

void BakeProgress::advance(double fraction, const std::string& detail) {
    if (quiet_) return;
    fmt::print(stream_, "{:<12} {:>3.0f}%  {:<20} {:6.2f} s\n", steps_.back().name, fraction * 100, detail,
               elapsedSeconds());
    std::fflush(stream_);
}

void BakeProgress::addDeviceTime(double milliseconds) {
    if (milliseconds > 0) steps_.back().deviceMilliseconds += milliseconds;
}

void BakeProgress::end() {
    steps_.back().wallMilliseconds = elapsedSeconds() * 1e3;
    advance(1);
}

double BakeProgress::elapsedSeconds() const {
    return std::chrono::duration<double>(Clock::now() - started_).count();
}

} // namespace iblkit::bake
