#include "scratch_folder.hpp"

#include <unistd.h>

#include <string>

namespace iblkit::files {
namespace {

std::filesystem::path freshFolder(std::string_view prefix) {
    auto path = std::filesystem::temp_directory_path() / ("iblkit-" + std::string(prefix) + "-" + std::to_string(getpid()));
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
