#pragma once

#include <filesystem>

namespace iblkit::files {

// From here on, SIGINT, SIGTERM and SIGHUP are blocked in this thread and in every thread it
// starts later, and one thread of its own waits for them: when one comes it removes every folder
// registered below, then ends the process as the signal would have. Call it first, before any
// library starts threads (a Vulkan driver does). Calling it again does nothing.
void cleanUpOnSignals();

// A folder to remove if the process is stopped by one of those signals while this lives.
class RemovedOnSignal {
public:
    explicit RemovedOnSignal(std::filesystem::path folder);
    ~RemovedOnSignal();
    RemovedOnSignal(const RemovedOnSignal&) = delete;
    RemovedOnSignal& operator=(const RemovedOnSignal&) = delete;

private:
    std::filesystem::path folder_;
};

} // namespace iblkit::files
