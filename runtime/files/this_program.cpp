#include "this_program.hpp"

#include <cstdlib>

namespace iblkit::files {

std::filesystem::path thisProgram() {
    if (const char* launcher = std::getenv("IBLKIT_LAUNCHER"); launcher && *launcher) return launcher;
    return std::filesystem::read_symlink("/proc/self/exe");
}

} // namespace iblkit::files
