// A batch's parts: I/N from the flag, or from a scheduler's array task, each line in exactly one part.
#include "batch_error.hpp"
#include "shard.hpp"

#include <gtest/gtest.h>

#include <map>

namespace iblkit::batch {
namespace {

Variables variables(std::map<std::string, std::string> values) {
    return [values](const char* name) -> std::optional<std::string> {
        const auto found = values.find(name);
        return found == values.end() ? std::nullopt : std::optional(found->second);
    };
}

TEST(Shard, EveryLineIsInExactlyOnePart) {
    for (uint32_t count : {1u, 2u, 3u, 7u}) {
        for (size_t line = 0; line < 50; ++line) {
            int holders = 0;
            for (uint32_t index = 0; index < count; ++index) holders += Shard{index, count}.holds(line);
            EXPECT_EQ(holders, 1) << line << " of " << count;
        }
    }
}

TEST(Shard, TheFlagIsIOfN) {
    EXPECT_EQ(parseShard("2/8").index, 2u);
    EXPECT_EQ(parseShard("2/8").count, 8u);
    EXPECT_EQ(parseShard("0/1").name(), "0-of-1");
    for (const char* bad : {"8/8", "1/0", "1", "a/2", "1/2/3", "-1/2", "1/ 2", ""}) EXPECT_THROW(parseShard(bad), BatchError) << bad;
}

TEST(Shard, SlurmsArrayTaskCountsFromItsFirstTask) {
    const auto shard = schedulerShard(variables({{"SLURM_ARRAY_TASK_ID", "7"}, {"SLURM_ARRAY_TASK_MIN", "5"},
                                                 {"SLURM_ARRAY_TASK_COUNT", "4"}}));
    ASSERT_TRUE(shard);
    EXPECT_EQ(shard->index, 2u);
    EXPECT_EQ(shard->count, 4u);
    const auto stepped = schedulerShard(variables({{"SLURM_ARRAY_TASK_ID", "6"}, {"SLURM_ARRAY_TASK_MIN", "0"},
                                                   {"SLURM_ARRAY_TASK_STEP", "2"}, {"SLURM_ARRAY_TASK_COUNT", "5"}}));
    EXPECT_EQ(stepped->index, 3u);
    EXPECT_THROW(schedulerShard(variables({{"SLURM_ARRAY_TASK_ID", "1"}})), BatchError);
    EXPECT_THROW(schedulerShard(variables({{"SLURM_ARRAY_TASK_ID", "x"}, {"SLURM_ARRAY_TASK_COUNT", "2"}})), BatchError);
    EXPECT_THROW(schedulerShard(variables({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "2"}})), BatchError);
}

TEST(Shard, KubernetesAndAwsBatchIndexes) {
    EXPECT_EQ(schedulerShard(variables({{"JOB_COMPLETION_INDEX", "3"}}), 5)->index, 3u);
    EXPECT_THROW(schedulerShard(variables({{"JOB_COMPLETION_INDEX", "3"}})), BatchError) << "the count is needed";
    EXPECT_EQ(schedulerShard(variables({{"AWS_BATCH_JOB_ARRAY_INDEX", "1"}, {"AWS_BATCH_JOB_ARRAY_SIZE", "2"}}))->count, 2u);
    EXPECT_EQ(schedulerShard(variables({{"AWS_BATCH_JOB_ARRAY_INDEX", "1"}}), 3)->count, 3u);
    EXPECT_FALSE(schedulerShard(variables({})));
}

} // namespace
} // namespace iblkit::batch
