#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace iblkit::reference {

// Runs row(0..rows-1) on every hardware thread; each thread takes the next row not yet taken,
// so rows of uneven cost still share the threads evenly.
// The first exception a row throws stops the other threads' work and is rethrown here.
template <typename Row>
void forEachRow(uint32_t rows, const Row& row) {
    std::atomic<uint32_t> next{0};
    std::exception_ptr failure;
    std::mutex failureMutex;
    const unsigned workers = std::max(1u, std::min(std::thread::hardware_concurrency(), rows));
    {
        std::vector<std::jthread> threads;
        for (unsigned w = 0; w < workers; ++w)
            threads.emplace_back([&] {
                try {
                    for (uint32_t r = next++; r < rows; r = next++) row(r);
                } catch (...) {
                    next = rows;
                    const std::lock_guard lock(failureMutex);
                    if (!failure) failure = std::current_exception();
                }
            });
    }
    if (failure) std::rethrow_exception(failure);
}

} // namespace iblkit::reference
