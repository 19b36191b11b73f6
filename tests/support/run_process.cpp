#include "run_process.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <thread>
#include <filesystem>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <string_view>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace iblkit::testing {
namespace {

std::string slurpAndRemove(const std::string& path) {
    std::ifstream stream(path, std::ios::binary);
    std::ostringstream text;
    text << stream.rdbuf();
    std::remove(path.c_str());
    return text.str();
}

} // namespace

ProcessResult runProcess(const std::vector<std::string>& command, const std::vector<std::string>& environment,
                         double killAfterSeconds, int killSignal) {
    const auto folder = std::filesystem::temp_directory_path().string();
    std::string outPath = folder + "/iblkit-out-XXXXXX";
    std::string errPath = folder + "/iblkit-err-XXXXXX";
    const int outFd = mkstemp(outPath.data());
    const int errFd = mkstemp(errPath.data());
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, outFd, 1);
    posix_spawn_file_actions_adddup2(&actions, errFd, 2);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    std::vector<char*> argv;
    for (const auto& argument : command) argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    std::vector<char*> envp;
    // A variable given here replaces the inherited one: getenv would find the inherited one first.
    const auto overridden = [&](const char* inherited) {
        return std::any_of(environment.begin(), environment.end(), [&](const std::string& given) {
            const auto name = given.substr(0, given.find('=') + 1);
            return std::string_view(inherited).starts_with(name);
        });
    };
    for (char** variable = environ; *variable; ++variable)
        if (!overridden(*variable)) envp.push_back(*variable);
    for (const auto& variable : environment) envp.push_back(const_cast<char*>(variable.c_str()));
    envp.push_back(nullptr);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    close(outFd);
    close(errFd);
    if (spawned != 0) throw std::runtime_error("cannot start " + command.front());
    int status = 0;
    if (killAfterSeconds > 0) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(killAfterSeconds);
        while (waitpid(pid, &status, WNOHANG) == 0) {
            if (std::chrono::steady_clock::now() >= deadline) {
                kill(pid, killSignal);
                waitpid(pid, &status, 0);
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
    } else {
        waitpid(pid, &status, 0);
    }
    return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), slurpAndRemove(outPath),
            slurpAndRemove(errPath)};
}

} // namespace iblkit::testing
