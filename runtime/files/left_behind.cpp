#include "left_behind.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <unistd.h>

namespace iblkit::files {
namespace fs = std::filesystem;

namespace {

std::string thisHost() {
    char host[256] = {};
    gethostname(host, sizeof host - 1);
    std::string name(host);
    std::replace(name.begin(), name.end(), '/', '_');
    return name;
}

bool processIsGone(std::string_view digits) {
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string_view::npos) return false;
    return kill(pid_t(std::stol(std::string(digits))), 0) != 0 && errno == ESRCH;
}

} // namespace

std::string writerTag() { return thisHost() + "-" + std::to_string(getpid()); }

bool leftByAGoneWriter(const fs::directory_entry& entry, std::string_view prefix) {
    const std::string name = entry.path().filename().string();
    const size_t at = name.find(prefix);
    if (at == std::string::npos) return false;
    // HOST-PID-XXXXXX after the prefix; the host may hold '-' itself.
    const std::string_view tagged = std::string_view(name).substr(at + prefix.size());
    const size_t suffix = tagged.rfind('-');
    const size_t dash = suffix == std::string_view::npos ? suffix : tagged.substr(0, suffix).rfind('-');
    if (dash != std::string_view::npos && tagged.substr(0, dash) == thisHost())
        return processIsGone(tagged.substr(dash + 1, suffix - dash - 1));
    std::error_code error;
    const auto written = entry.last_write_time(error);
    return !error && fs::file_time_type::clock::now() - written > std::chrono::hours(24);
}

void removeLeftBehind(const fs::path& folder, std::string_view prefix) {
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(folder, error))
        if (leftByAGoneWriter(entry, prefix)) fs::remove_all(entry.path(), error);
}

} // namespace iblkit::files
