#include "signal_cleanup.hpp"

#include <algorithm>
#include <csignal>
#include <mutex>
#include <pthread.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace iblkit::files {
namespace {

std::mutex& registryMutex() {
    static std::mutex mutex;
    return mutex;
}

std::vector<std::filesystem::path>& registry() {
    static std::vector<std::filesystem::path> folders;
    return folders;
}

sigset_t stoppingSignals() {
    sigset_t signals;
    sigemptyset(&signals);
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&signals, signal);
    return signals;
}

[[noreturn]] void waitAndCleanUp(sigset_t signals) {
    int signal = 0;
    while (sigwait(&signals, &signal) != 0) {}
    {
        const std::lock_guard lock(registryMutex());
        for (const auto& folder : registry()) {
            std::error_code ignored;
            std::filesystem::remove_all(folder, ignored);
        }
    }
    // End as the signal would have: its default action, delivered to this thread.
    std::signal(signal, SIG_DFL);
    pthread_sigmask(SIG_UNBLOCK, &signals, nullptr);
    raise(signal);
    _exit(128 + signal);
}

} // namespace

void cleanUpOnSignals() {
    static std::once_flag started;
    std::call_once(started, [] {
        const sigset_t signals = stoppingSignals();
        pthread_sigmask(SIG_BLOCK, &signals, nullptr);
        std::thread(waitAndCleanUp, signals).detach();
    });
}

RemovedOnSignal::RemovedOnSignal(std::filesystem::path folder) : folder_(std::move(folder)) {
    const std::lock_guard lock(registryMutex());
    registry().push_back(folder_);
}

RemovedOnSignal::~RemovedOnSignal() {
    const std::lock_guard lock(registryMutex());
    auto& folders = registry();
    folders.erase(std::find(folders.begin(), folders.end(), folder_));
}

} // namespace iblkit::files
