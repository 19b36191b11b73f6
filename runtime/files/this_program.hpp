#pragma once

#include <filesystem>

namespace iblkit::files {

// The iblkit a user runs: the launcher that started this program ($IBLKIT_LAUNCHER, which it
// sets), else this program itself. For commands written down to run later or timed as a user runs them.
std::filesystem::path thisProgram();

} // namespace iblkit::files
