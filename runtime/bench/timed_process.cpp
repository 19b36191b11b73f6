#include "timed_process.hpp"

#include "bench_error.hpp"

#include <fmt/core.h>

#include <cerrno>
#include <chrono>
#include <fstream>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace iblkit::bench {
namespace {

std::string lastLine(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::string line, last;
    while (std::getline(in, line))
        if (!line.empty()) last = line;
    return last;
}

// posix_spawn's file actions, freed whatever happens.
class FileActions {
public:
    FileActions() { posix_spawn_file_actions_init(&actions_); }
    ~FileActions() { posix_spawn_file_actions_destroy(&actions_); }
    FileActions(const FileActions&) = delete;
    FileActions& operator=(const FileActions&) = delete;
    posix_spawn_file_actions_t* get() { return &actions_; }

private:
    posix_spawn_file_actions_t actions_;
};

} // namespace

double runTimed(const std::vector<std::string>& arguments, const std::filesystem::path& output,
                const std::filesystem::path& errorLog, const std::string& what) {
    std::vector<char*> argv;
    for (const auto& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    FileActions actions;
    posix_spawn_file_actions_addopen(actions.get(), STDOUT_FILENO, output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(actions.get(), STDERR_FILENO, errorLog.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const auto start = std::chrono::steady_clock::now();
    pid_t child = 0;
    if (const int error = posix_spawn(&child, argv[0], actions.get(), nullptr, argv.data(), environ); error != 0)
        throw BenchError(fmt::format("could not {}: cannot start {}", what, arguments.front()));
    int status = 0;
    while (waitpid(child, &status, 0) < 0)
        if (errno != EINTR) throw BenchError(fmt::format("could not {}: lost the process", what));
    const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw BenchError(fmt::format("could not {}: {}", what, lastLine(errorLog)));
    return wall;
}

} // namespace iblkit::bench
