#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace iblkit::batch {

// The I-th of N parts of a list: line k (counted from 0 among the list's bakes) is in part k mod N,
// so the parts stay balanced however the list is ordered and are the same on every machine.
struct Shard {
    uint32_t index = 0;
    uint32_t count = 1;
    bool holds(size_t position) const { return position % count == index; }
    std::string name() const; // "2-of-8"
};

// "I/N", with 0 <= I < N. Throws BatchError.
Shard parseShard(const std::string& text);

// The part a scheduler's array task is, from its own variables (read through `variable`):
// SLURM_ARRAY_TASK_ID less SLURM_ARRAY_TASK_MIN, of SLURM_ARRAY_TASK_COUNT; Kubernetes'
// JOB_COMPLETION_INDEX of `count`; AWS_BATCH_JOB_ARRAY_INDEX of AWS_BATCH_JOB_ARRAY_SIZE or `count`.
// None where no scheduler's variable is set. Throws BatchError for a variable that is not a count,
// an index past the count, or an index without a count.
using Variables = std::function<std::optional<std::string>(const char* name)>;
std::optional<Shard> schedulerShard(const Variables& variable, std::optional<uint32_t> count = std::nullopt);
Variables environmentVariables();

} // namespace iblkit::batch
