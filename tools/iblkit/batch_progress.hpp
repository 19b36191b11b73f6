#pragma once

#include "batch_record.hpp"

#include <iblkit/batch.hpp>

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <string>

namespace iblkit::cli {

// A line on stderr as each bake of a batch ends (a failure even when quiet), and on a terminal a
// status line after it: how many are left and about how long they will take, at the pace so far.
class BatchProgress {
public:
    BatchProgress(size_t bakes, bool quiet);
    // `failure`: why a bake that returned its files still failed (a validation message), else empty.
    void ended(const BatchResult& result, size_t line, const std::string& failure = {});

private:
    size_t bakes_, ended_ = 0;
    bool quiet_, terminal_;
    std::chrono::steady_clock::time_point started_;
};

// "batch: 9 baked, 0 done already, 0 failed, 0 not baked (DIR/batch.json)".
void printBatchCounts(const batch::BatchRecord& record, const std::filesystem::path& recordFile);

} // namespace iblkit::cli
