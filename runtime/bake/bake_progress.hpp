#pragma once

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace iblkit::bake {

// A named part of a step (one mip of the prefilter, the source cube's mip chain): its own times.
struct PartTiming {
    std::string name;
    double deviceMilliseconds = 0;
    double wallMilliseconds = 0;
};

struct StepTiming {
    std::string name;
    double deviceMilliseconds = 0; // summed over the step's dispatches; 0 for host-only steps
    double wallMilliseconds = 0;
    std::vector<PartTiming> parts;  // where the step reports them, in order
    double peakMebibytes = 0;       // the process's largest resident set when the step ended (VmHWM; 0 without /proc)
};

// Reports each step on stderr unless quiet, and keeps every step's device and wall time for the
// summary. On a terminal a step's line is rewritten as it goes ("prefilter  60%  mip 3 of 5  2.1 s",
// at most ten times a second); anywhere else (a log file, a pipe) each step is one line, written
// when it ends.
class BakeProgress {
public:
    explicit BakeProgress(bool quiet, std::FILE* stream = stderr);

    void begin(const std::string& step);
    void advance(double fraction, const std::string& detail = {});
    void addDeviceTime(double milliseconds);
    // Starts a named part of the current step; it ends where the next part starts or the step
    // ends, and takes the device time added while it runs.
    void part(const std::string& name);
    void end();

    const std::vector<StepTiming>& steps() const { return steps_; }

private:
    using Clock = std::chrono::steady_clock;
    double elapsedSeconds() const;

    void print(double fraction, const std::string& detail, const char* end);
    void endPart();

    bool quiet_;
    std::FILE* stream_;
    bool terminal_;
    std::vector<StepTiming> steps_;
    Clock::time_point started_;
    Clock::time_point partStarted_;
    bool inPart_ = false;
    Clock::time_point lastShown_;
    std::string lastDetail_;
};

// This process's largest resident set so far, as the kernel keeps it (VmHWM in /proc/self/status;
// 0 without it). The kernel's ru_maxrss would not do for a process started by vfork: it counts the
// parent's.
double peakResidentMebibytes();

} // namespace iblkit::bake
