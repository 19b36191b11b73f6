#include "batch_command.hpp"

#include "bake_command.hpp"
#include "batch_lines.hpp"
#include "batch_progress.hpp"
#include "signal_cleanup.hpp"
#include "this_program.hpp"

#include "batch_error.hpp"
#include "batch_record.hpp"
#include "sha256.hpp"
#include "shard.hpp"
#include "slurm_script.hpp"

#include <iblkit/batch.hpp>
#include <iblkit/version.hpp>

#include <fmt/core.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>

namespace iblkit::cli {
namespace {

namespace fs = std::filesystem;

struct BatchArguments {
    std::string list;
    fs::path output;
    std::string cache;
    bool noCache = false;
    std::string device;
    bool validation = false;
    bool quiet = false;
    bool json = false;
    std::string shard;
    std::optional<uint32_t> shards;
    std::string merge;
    bool slurmScript = false;
    std::optional<uint32_t> cpusPerTask;
    bool force = false;
};

batch::Shard chosenShard(const BatchArguments& arguments) {
    if (!arguments.shard.empty()) return batch::parseShard(arguments.shard);
    if (const auto shard = batch::schedulerShard(batch::environmentVariables(), arguments.shards)) return *shard;
    return {};
}

std::optional<fs::path> cacheOf(const BatchArguments& arguments) {
    if (arguments.noCache && !arguments.cache.empty()) throw CLI::ValidationError("--cache and --no-cache", "give one of them");
    if (arguments.noCache) return std::nullopt;
    return arguments.cache.empty() ? defaultCacheFolder() : fs::path(arguments.cache);
}

// `batch` with the same list, folder and process flags, every path absolute, for each array task.
std::vector<std::string> taskArguments(const BatchArguments& arguments, const std::optional<fs::path>& cache) {
    std::vector<std::string> words{"batch", fs::absolute(arguments.list).string(), "-o", fs::absolute(arguments.output).string()};
    if (cache) words.insert(words.end(), {"--cache", fs::absolute(*cache).string()});
    else words.push_back("--no-cache");
    if (!arguments.device.empty()) words.insert(words.end(), {"--device", arguments.device});
    if (arguments.validation) words.push_back("--validate");
    if (arguments.force) words.push_back("--force");
    words.push_back("--quiet"); // each task's log is its own file: the records hold the status
    return words;
}

void printSlurmScript(const BatchArguments& arguments, size_t lines) {
    const auto cache = cacheOf(arguments);
    // Four lines a task by default: a task's device and kernels serve several bakes, and the parts stay many.
    const uint32_t shards = arguments.shards.value_or(uint32_t((lines + 3) / 4));
    if (shards == 0 || shards > lines)
        throw batch::BatchError(fmt::format("--shards: error: {} parts of a list of {} bakes", shards, lines));
    const fs::path logs = fs::absolute(arguments.output) / "batch-shards";
    fs::create_directories(logs); // sbatch opens each task's output file there before the task starts
    fmt::print("{}", batch::slurmScript({files::thisProgram(), taskArguments(arguments, cache), logs, fs::current_path(), shards,
                                         arguments.cpusPerTask.value_or(0), "iblkit-batch"}));
}

// Exit status 1 with one line where anything is not done.
void requireAllDone(const batch::BatchRecord& record, const fs::path& recordFile, size_t missingShards = 0) {
    size_t failed = 0, pending = 0;
    for (const auto& entry : record.bakes) {
        failed += entry.status == "failed";
        pending += entry.status == "pending";
    }
    if (failed || pending || missingShards)
        throw std::runtime_error(fmt::format("batch: {} failed, {} not baked, {} part{} without a record (see {})", failed,
                                             pending, missingShards, missingShards == 1 ? "" : "s", recordFile.string()));
}

void runMerge(const BatchArguments& arguments) {
    const fs::path folder = arguments.merge;
    std::vector<std::string> unreadable;
    const auto records = batch::readRecords(folder, &unreadable);
    for (const auto& path : unreadable) fmt::print(stderr, "warning: {}: not a batch record; left out\n", path);
    if (records.empty()) throw batch::BatchError(folder.string() + ": error: no batch record (batch.json or batch-shards/)");
    const auto merged = batch::mergeRecords(records);
    const auto path = folder / "batch.json";
    batch::writeRecord(path, merged.record);
    if (arguments.json) fmt::print("{}", batch::recordText(merged.record));
    for (const auto& shard : merged.missing) fmt::print(stderr, "part {} of {}: no record\n", shard.index, shard.count);
    if (!arguments.quiet) printBatchCounts(merged.record, path);
    requireAllDone(merged.record, path, merged.missing.size());
}

// The lines of this part, each as a record entry: done where an earlier run baked it whole, pending otherwise.
batch::RecordEntry entryFor(const BatchLineRequest& line, const std::map<std::string, batch::RecordEntry>& earlier,
                            const BatchArguments& arguments) {
    std::vector<fs::path> inputs;
    if (line.request.environment) inputs.push_back(*line.request.environment);
    if (line.request.scene) inputs.push_back(*line.request.scene);
    batch::RecordEntry entry;
    entry.name = line.line.name;
    entry.line = line.line.number;
    entry.fingerprint = batch::bakeFingerprint(version(), line.line.arguments, arguments.device, inputs);
    const auto found = earlier.find(line.line.name);
    if (arguments.force || found == earlier.end() || entry.fingerprint.empty()) return entry;
    const auto& before = found->second;
    if ((before.status == "baked" || before.status == "done") && before.fingerprint == entry.fingerprint &&
        batch::stillWhole(before, arguments.output / before.name)) {
        entry.status = "done";
        entry.files = before.files;
        entry.finished = before.finished;
    }
    return entry;
}

BakeRequest withProcessFlags(BakeRequest request, const BatchArguments& arguments, const std::optional<fs::path>& cache) {
    request.cache = cache;
    request.device = arguments.device;
    request.validation = arguments.validation;
    request.quiet = true; // the batch reports each bake as it ends
    return request;
}

void runBatch(const BatchArguments& arguments) {
    if (arguments.list.empty()) throw CLI::RequiredError("LIST");
    if (arguments.output.empty()) throw CLI::RequiredError("--output");
    const auto lines = batchLineRequests(batch::readBatchList(arguments.list), arguments.list);
    if (arguments.slurmScript) return printSlurmScript(arguments, lines.size());
    const auto shard = chosenShard(arguments);
    const auto cache = cacheOf(arguments);
    fs::create_directories(arguments.output);

    batch::BatchRecord record{arguments.list, cache::sha256OfFile(arguments.list), lines.size(), shard, {}, batch::utcNow(), {}, {}};
    const auto earlier = batch::latestEntries(batch::readRecords(arguments.output));
    std::vector<BatchBake> bakes;
    std::map<std::string, size_t> entryOf;
    for (size_t position = 0; position < lines.size(); ++position) {
        if (!shard.holds(position)) continue;
        const auto& line = lines[position];
        entryOf[line.line.name] = record.bakes.size();
        record.bakes.push_back(entryFor(line, earlier, arguments));
        if (record.bakes.back().status == "pending")
            bakes.push_back({line.line.name, withProcessFlags(line.request, arguments, cache)});
    }
    const auto recordFile = batch::recordPath(arguments.output, shard);
    batch::writeRecord(recordFile, record);

    BatchProgress progress(bakes.size(), arguments.quiet);
    BatchOptions options;
    options.onResult = [&](const BatchResult& result) {
        auto& entry = record.bakes[entryOf.at(result.name)];
        entry.wallMilliseconds = result.wallMilliseconds;
        entry.finished = batch::utcNow();
        entry.status = result.summary ? "baked" : "failed";
        if (result.error) entry.error = result.error->what();
        if (result.summary && !result.summary->validationMessages.empty()) { // --validate: a message fails the bake
            const auto& messages = result.summary->validationMessages;
            entry.status = "failed";
            entry.error = fmt::format("validation: {} ({} messages)", messages.front(), messages.size());
        }
        if (result.summary) {
            for (const auto& file : result.summary->files) entry.files.push_back({file.name, file.sha256, file.bytes});
            for (const auto& step : result.summary->steps)
                entry.steps.push_back({step.name, step.deviceMilliseconds, step.wallMilliseconds});
        }
        batch::writeRecord(recordFile, record); // as each ends: a task stopped midway leaves what it did
        progress.ended(result, entry.line, entry.status == "failed" ? entry.error : std::string());
    };
    bakeBatch(bakes, arguments.output, options);
    record.finished = batch::utcNow();
    batch::writeRecord(recordFile, record);
    if (arguments.json) fmt::print("{}", batch::recordText(record));
    if (!arguments.quiet) printBatchCounts(record, recordFile);
    requireAllDone(record, recordFile);
}

} // namespace

void addBatchCommand(CLI::App& app) {
    auto arguments = std::make_shared<BatchArguments>();
    auto* command = app.add_subcommand(
        "batch", "Bake every line of a list (NAME [ENV] [bake flags]) into DIR/NAME in one process; a part of it per "
                 "scheduler task (docs/batch.md)");
    command->add_option("LIST", arguments->list, "A text file: one bake a line, `NAME [ENV] [flags of iblkit bake]`, # comments");
    command->add_option("-o,--output", arguments->output, "The batch's folder: each line's bake goes to DIR/NAME, the record to DIR/batch.json");
    command->add_option("--cache", arguments->cache,
                        "Cache folder shared by every bake, and by every machine that mounts it (default "
                        "$XDG_CACHE_HOME/iblkit, else ~/.cache/iblkit)");
    command->add_flag("--no-cache", arguments->noCache, "Compute everything, and keep nothing");
    command->add_option("--device", arguments->device, "Device index or part of its name (default: lavapipe)");
    command->add_flag("--validate", arguments->validation, "Run with the Vulkan validation layer; any message fails its bake");
    command->add_option("--shard", arguments->shard,
                        "Bake only part I of N (I from 0; line k is in part k mod N). Default: from the scheduler's "
                        "array task ($SLURM_ARRAY_TASK_ID, $JOB_COMPLETION_INDEX, $AWS_BATCH_JOB_ARRAY_INDEX), else all");
    command->add_option("--shards", arguments->shards,
                        "The number of parts: for Kubernetes' and AWS Batch's index, and the tasks of --slurm-script "
                        "(default there: a task per four lines)")
        ->check(CLI::Range(1u, 1000000u));
    command->add_flag("--slurm-script", arguments->slurmScript,
                      "Print an sbatch script: an array over the parts, each task running this batch on its part");
    command->add_option("--cpus-per-task", arguments->cpusPerTask, "With --slurm-script: the CPUs each task asks for")
        ->check(CLI::Range(1u, 4096u));
    command->add_option("--merge", arguments->merge,
                        "Merge every part's record in this batch folder into its batch.json, print the whole status, "
                        "and exit 1 unless every line is done");
    command->add_flag("--force", arguments->force, "Bake every line, even those an earlier run left done and whole");
    command->add_flag("-q,--quiet", arguments->quiet, "No progress on stderr (failures are still reported)");
    command->add_flag("--json", arguments->json, "Print the record (as batch.json holds it) on stdout at the end");
    command->callback([arguments] {
        files::cleanUpOnSignals(); // first: the Vulkan driver's threads must inherit the blocked signals
        if (!arguments->merge.empty()) return runMerge(*arguments);
        runBatch(*arguments);
    });
}

} // namespace iblkit::cli
