#pragma once

#include "shard.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::batch {

struct RecordedFile {
    std::string name; // relative to the bake's folder
    std::string sha256;
    uint64_t bytes = 0;
};

// One line's outcome. Status: "baked" (by this run), "done" (found done and whole, not baked
// again), "failed" (with the error), "pending" (not reached yet: a run stopped before it).
struct RecordEntry {
    std::string name;
    size_t line = 0;
    std::string status = "pending";
    std::string error;
    double wallMilliseconds = 0;
    std::string fingerprint; // of what the bake depends on (bakeFingerprint)
    std::vector<RecordedFile> files;
    std::string finished; // UTC, ISO 8601, when it ended
    // Each step's device and wall time, as `iblkit bake --json` gives them (a baked line's).
    struct Step {
        std::string name;
        double deviceMilliseconds = 0, wallMilliseconds = 0;
    };
    std::vector<Step> steps;
};

// What one run of a part of a list did: DIR/batch.json for the whole list, DIR/batch-shards/I-of-N.json
// for a part. Written anew, atomically, as each bake ends.
struct BatchRecord {
    std::string list;       // the list's path as given
    std::string listSha256; // of its bytes
    size_t lines = 0;       // the list's bakes, in all parts
    Shard shard;
    std::vector<Shard> merged; // the parts a merged record was made of
    std::string started, finished;
    std::vector<RecordEntry> bakes; // this part's, in the list's order
};

std::filesystem::path recordPath(const std::filesystem::path& folder, const Shard& shard);
void writeRecord(const std::filesystem::path& path, const BatchRecord& record); // throws BatchError
std::string recordText(const BatchRecord& record); // the JSON a record file holds
// Every record in the folder (batch.json and batch-shards/*.json). A record that does not parse is
// left out, its path in `unreadable`.
std::vector<BatchRecord> readRecords(const std::filesystem::path& folder, std::vector<std::string>* unreadable = nullptr);

// The latest entry of each line over `records` (by when it finished; pending ones last).
std::map<std::string, RecordEntry> latestEntries(const std::vector<BatchRecord>& records);

// The whole status from every part's record: each line's latest entry, in the list's order, and the
// parts of the latest list's split with no record (`missing`).
struct MergedRecord {
    BatchRecord record;
    std::vector<Shard> missing;
};
MergedRecord mergeRecords(const std::vector<BatchRecord>& records);

// Whether the entry's folder still holds exactly what it recorded: each file, with its hash.
bool stillWhole(const RecordEntry& entry, const std::filesystem::path& folder);

// The fingerprint of a line: the program (its version and build), the line's words, the device
// chosen, and the bytes of every input file it reads (the environment, a folder's faces, a scene).
// Empty when an input cannot be read: such a line is never taken as done.
std::string bakeFingerprint(const std::string& toolVersion, const std::vector<std::string>& words, const std::string& device,
                            const std::vector<std::filesystem::path>& inputs);

std::string utcNow(); // "2026-11-29T15:40:00.123Z"

} // namespace iblkit::batch
