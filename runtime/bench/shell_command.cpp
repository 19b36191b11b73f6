#include "shell_command.hpp"

#include "bench_error.hpp"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <sys/wait.h>

namespace iblkit::bench {

std::string shellQuoted(const std::filesystem::path& path) {
    std::string text = "'";
    for (const char c : path.string()) text += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return text + "'";
}

void runShell(const std::string& command, const std::string& what) {
    if (std::system(command.c_str()) != 0) throw BenchError("could not " + what + " (" + command + ")");
}

int runWithInput(const std::string& command, const std::string& input) {
    struct sigaction ignore {}, previous{};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &ignore, &previous);
    int status = -1;
    if (std::FILE* child = popen(command.c_str(), "w")) {
        const bool written = std::fwrite(input.data(), 1, input.size(), child) == input.size();
        const int closed = pclose(child);
        status = written && WIFEXITED(closed) ? WEXITSTATUS(closed) : -1;
    }
    sigaction(SIGPIPE, &previous, nullptr);
    return status;
}

} // namespace iblkit::bench
