#pragma once

#include "signal_cleanup.hpp"

#include <filesystem>
#include <string_view>

namespace iblkit::files {

// A fresh folder of this process's under the system's temporary folder ("iblkit-PREFIX-PID"),
// removed with everything in it when this ends, or when SIGINT, SIGTERM or SIGHUP stop the
// process (once cleanUpOnSignals was called). Throws FileError when the system's temporary folder
// (TMPDIR) is not usable.
class ScratchFolder {
public:
    explicit ScratchFolder(std::string_view prefix);
    ~ScratchFolder();
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;

    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
    RemovedOnSignal removedOnSignal_;
};

} // namespace iblkit::files
