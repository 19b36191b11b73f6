#include "scratch_folder.hpp"

#include "atomic_output.hpp"

#include <unistd.h>

#include <cstdlib>
#include <string>

namespace iblkit::files {
namespace {

std::filesystem::path temporaryFolder() {
    try {
        return std::filesystem::temp_directory_path();
    } catch (const std::filesystem::filesystem_error& error) {
        const char* named = std::getenv("TMPDIR");
        throw FileError("no scratch folder can be made: the system's temporary folder" +
                        (named ? " (TMPDIR '" + std::string(named) + "')" : std::string()) + " is not usable (" +
                        error.code().message() + ")");
    }
}

std::filesystem::path freshFolder(std::string_view prefix) {
    auto path = temporaryFolder() / ("iblkit-" + std::string(prefix) + "-" + std::to_string(getpid()));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
    return path;
}

} // namespace

ScratchFolder::ScratchFolder(std::string_view prefix) : path_(freshFolder(prefix)), removedOnSignal_(path_) {}

ScratchFolder::~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
}

} // namespace iblkit::files
