#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::batch {

struct SlurmScript {
    std::filesystem::path program;     // the iblkit to run, absolute
    std::vector<std::string> arguments; // `batch LIST -o DIR --cache CACHE ...`, absolute paths, without --shard
    std::filesystem::path logFolder;   // where each task's own output goes (DIR/batch-shards)
    std::filesystem::path workingFolder; // where the tasks run: the list's relative paths are read from there
    uint32_t shards = 1;
    uint32_t cpusPerTask = 0; // 0: the site's default
    std::string jobName = "iblkit-batch";
};

// A script for `sbatch`: an array of `shards` tasks, each running the same command, which finds its
// part in $SLURM_ARRAY_TASK_ID. Every word is quoted for the shell.
std::string slurmScript(const SlurmScript& script);

std::string shellQuoted(const std::string& word);

} // namespace iblkit::batch
