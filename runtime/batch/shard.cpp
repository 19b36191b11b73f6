#include "shard.hpp"

#include "batch_error.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cstdlib>

namespace iblkit::batch {
namespace {

std::optional<uint32_t> countOf(std::string_view text) {
    uint32_t value = 0;
    const auto end = text.data() + text.size();
    const auto [at, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || at != end) return std::nullopt;
    return value;
}

uint32_t variableCount(const char* name, const std::string& value) {
    const auto count = countOf(value);
    if (!count) throw BatchError(fmt::format("${}: error: '{}' is not a whole number", name, value));
    return *count;
}

Shard checked(uint32_t index, uint32_t count, const std::string& source) {
    if (count == 0) throw BatchError(fmt::format("{}: error: the number of parts is 0", source));
    if (index >= count) throw BatchError(fmt::format("{}: error: part {} of {} (parts count from 0)", source, index, count));
    return {index, count};
}

} // namespace

std::string Shard::name() const { return fmt::format("{}-of-{}", index, count); }

Shard parseShard(const std::string& text) {
    const size_t slash = text.find('/');
    const auto index = slash == std::string::npos ? std::nullopt : countOf(std::string_view(text).substr(0, slash));
    const auto count = slash == std::string::npos ? std::nullopt : countOf(std::string_view(text).substr(slash + 1));
    if (!index || !count) throw BatchError(fmt::format("--shard: error: '{}' is not I/N (the I-th of N parts, from 0)", text));
    return checked(*index, *count, "--shard " + text);
}

std::optional<Shard> schedulerShard(const Variables& variable, std::optional<uint32_t> count) {
    if (const auto id = variable("SLURM_ARRAY_TASK_ID")) {
        const uint32_t task = variableCount("SLURM_ARRAY_TASK_ID", *id);
        const auto min = variable("SLURM_ARRAY_TASK_MIN");
        const uint32_t first = min ? variableCount("SLURM_ARRAY_TASK_MIN", *min) : 0;
        const auto tasks = variable("SLURM_ARRAY_TASK_COUNT");
        if (!tasks) throw BatchError("$SLURM_ARRAY_TASK_ID: error: set without $SLURM_ARRAY_TASK_COUNT");
        if (task < first) throw BatchError("$SLURM_ARRAY_TASK_ID: error: below $SLURM_ARRAY_TASK_MIN");
        // An array with a step (--array=0-9:2) numbers its tasks apart: the count, not the ids, is what is shared.
        const auto step = variable("SLURM_ARRAY_TASK_STEP");
        const uint32_t stride = step ? std::max(1u, variableCount("SLURM_ARRAY_TASK_STEP", *step)) : 1;
        return checked((task - first) / stride, variableCount("SLURM_ARRAY_TASK_COUNT", *tasks), "$SLURM_ARRAY_TASK_ID");
    }
    if (const auto index = variable("JOB_COMPLETION_INDEX")) {
        if (!count) throw BatchError("$JOB_COMPLETION_INDEX: error: give the number of parts with --shards N (the Job's completions)");
        return checked(variableCount("JOB_COMPLETION_INDEX", *index), *count, "$JOB_COMPLETION_INDEX");
    }
    if (const auto index = variable("AWS_BATCH_JOB_ARRAY_INDEX")) {
        const auto size = variable("AWS_BATCH_JOB_ARRAY_SIZE");
        if (!size && !count) throw BatchError("$AWS_BATCH_JOB_ARRAY_INDEX: error: give the number of parts with --shards N (the array's size)");
        const uint32_t parts = size ? variableCount("AWS_BATCH_JOB_ARRAY_SIZE", *size) : *count;
        return checked(variableCount("AWS_BATCH_JOB_ARRAY_INDEX", *index), parts, "$AWS_BATCH_JOB_ARRAY_INDEX");
    }
    return std::nullopt;
}

Variables environmentVariables() {
    return [](const char* name) -> std::optional<std::string> {
        const char* value = std::getenv(name);
        return value && *value ? std::optional<std::string>(value) : std::nullopt;
    };
}

} // namespace iblkit::batch
