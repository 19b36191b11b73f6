#pragma once

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace iblkit::bake {

struct StepTiming {
    std::string name;
    double deviceMilliseconds = 0; // summed over the step's dispatches; 0 for host-only steps
    double wallMilliseconds = 0;
};

// Reports each step on stderr as it goes ("prefilter  60%  mip 3 of 5  2.1 s") unless quiet,
// and keeps every step's device and wall time for the summary.
class BakeProgress {
public:
    explicit BakeProgress(bool quiet, std::FILE* stream = stderr) : quiet_(quiet), stream_(stream) {}

    void begin(const std::string& step);
    void advance(double fraction, const std::string& detail = {});
    void addDeviceTime(double milliseconds);
    void end();

    const std::vector<StepTiming>& steps() const { return steps_; }

private:
    using Clock = std::chrono::steady_clock;
    double elapsedSeconds() const;

    bool quiet_;
    std::FILE* stream_;
    std::vector<StepTiming> steps_;
    Clock::time_point started_;
};

} // namespace iblkit::bake
