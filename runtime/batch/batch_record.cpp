#include "batch_record.hpp"

#include "batch_error.hpp"
#include "cache_key.hpp"
#include "sha256.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <ctime>
#include <fstream>
#include <set>
#include <unistd.h>

namespace iblkit::batch {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json fileJson(const RecordedFile& file) { return {{"name", file.name}, {"sha256", file.sha256}, {"bytes", file.bytes}}; }

json entryJson(const RecordEntry& entry) {
    json files = json::array();
    for (const auto& file : entry.files) files.push_back(fileJson(file));
    json out{{"name", entry.name},         {"line", entry.line},         {"status", entry.status},
             {"wall_ms", entry.wallMilliseconds}, {"fingerprint", entry.fingerprint}, {"files", files},
             {"finished", entry.finished}};
    if (!entry.error.empty()) out["error"] = entry.error;
    if (!entry.steps.empty()) {
        out["steps"] = json::array();
        for (const auto& step : entry.steps)
            out["steps"].push_back({{"name", step.name}, {"device_ms", step.deviceMilliseconds}, {"wall_ms", step.wallMilliseconds}});
    }
    return out;
}

RecordEntry entryOf(const json& in) {
    RecordEntry entry{in.at("name").get<std::string>(), in.at("line").get<size_t>(), in.at("status").get<std::string>(),
                      in.value("error", std::string()), in.value("wall_ms", 0.0), in.value("fingerprint", std::string()),
                      {}, in.value("finished", std::string()), {}};
    for (const auto& file : in.value("files", json::array()))
        entry.files.push_back({file.at("name").get<std::string>(), file.at("sha256").get<std::string>(),
                               file.at("bytes").get<uint64_t>()});
    for (const auto& step : in.value("steps", json::array()))
        entry.steps.push_back({step.at("name").get<std::string>(), step.value("device_ms", 0.0), step.value("wall_ms", 0.0)});
    return entry;
}

json shardJson(const Shard& shard) { return json::array({shard.index, shard.count}); }
Shard shardOf(const json& in) { return {in.at(0).get<uint32_t>(), in.at(1).get<uint32_t>()}; }

json recordJson(const BatchRecord& record) {
    json bakes = json::array(), merged = json::array();
    std::map<std::string, size_t> counts{{"baked", 0}, {"done", 0}, {"failed", 0}, {"pending", 0}};
    for (const auto& entry : record.bakes) {
        bakes.push_back(entryJson(entry));
        ++counts[entry.status];
    }
    for (const auto& shard : record.merged) merged.push_back(shardJson(shard));
    json out{{"list", record.list},       {"list_sha256", record.listSha256}, {"lines", record.lines},
             {"shard", shardJson(record.shard)}, {"started", record.started},      {"finished", record.finished},
             {"counts", counts},          {"bakes", bakes}};
    if (!record.merged.empty()) out["merged"] = merged;
    return out;
}

BatchRecord recordOf(const json& in) {
    BatchRecord record{in.at("list").get<std::string>(), in.at("list_sha256").get<std::string>(), in.at("lines").get<size_t>(),
                       shardOf(in.at("shard")), {}, in.value("started", std::string()), in.value("finished", std::string()), {}};
    for (const auto& shard : in.value("merged", json::array())) record.merged.push_back(shardOf(shard));
    for (const auto& entry : in.at("bakes")) record.bakes.push_back(entryOf(entry));
    return record;
}

std::optional<BatchRecord> readRecord(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    const auto parsed = json::parse(in, nullptr, false);
    if (parsed.is_discarded()) return std::nullopt;
    try {
        return recordOf(parsed);
    } catch (const json::exception&) {
        return std::nullopt;
    }
}

// Later first; a pending entry (no end) after any that ended.
bool finishedLater(const RecordEntry& a, const RecordEntry& b) {
    if ((a.status == "pending") != (b.status == "pending")) return b.status == "pending";
    return a.finished > b.finished;
}

void addInput(cache::CacheKey& key, const fs::path& input) {
    if (fs::is_directory(input)) {
        std::set<fs::path> files;
        for (const auto& item : fs::directory_iterator(input))
            if (item.is_regular_file()) files.insert(item.path());
        for (const auto& file : files) key.add("file", file.filename().string()).add("sha256", cache::sha256OfFile(file));
        return;
    }
    key.add("file", input.string()).add("sha256", cache::sha256OfFile(input));
}

} // namespace

std::string recordText(const BatchRecord& record) { return recordJson(record).dump(2) + "\n"; }

fs::path recordPath(const fs::path& folder, const Shard& shard) {
    return shard.count == 1 ? folder / "batch.json" : folder / "batch-shards" / (shard.name() + ".json");
}

void writeRecord(const fs::path& path, const BatchRecord& record) {
    static std::atomic<uint64_t> counter{0};
    std::error_code error;
    fs::create_directories(path.parent_path(), error);
    char host[256] = {};
    gethostname(host, sizeof host - 1);
    // Beside its place, under a name no other writer uses (on a shared folder, other machines' too).
    const fs::path temporary = path.string() + fmt::format(".tmp-{}-{}-{}", host, getpid(), counter++);
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << recordText(record);
        out.flush();
        if (!out) {
            fs::remove(temporary, error);
            throw BatchError(path.string() + ": error: cannot write the batch's record");
        }
    }
    fs::rename(temporary, path, error);
    if (error) {
        fs::remove(temporary, error);
        throw BatchError(path.string() + ": error: cannot put the batch's record in place: " + error.message());
    }
}

std::vector<BatchRecord> readRecords(const fs::path& folder, std::vector<std::string>* unreadable) {
    std::vector<fs::path> paths;
    if (fs::is_regular_file(folder / "batch.json")) paths.push_back(folder / "batch.json");
    std::error_code error;
    if (fs::is_directory(folder / "batch-shards", error))
        for (const auto& item : fs::directory_iterator(folder / "batch-shards"))
            if (item.is_regular_file() && item.path().extension() == ".json") paths.push_back(item.path());
    std::sort(paths.begin(), paths.end());
    std::vector<BatchRecord> records;
    for (const auto& path : paths) {
        if (auto record = readRecord(path)) records.push_back(std::move(*record));
        else if (unreadable) unreadable->push_back(path.string());
    }
    return records;
}

std::map<std::string, RecordEntry> latestEntries(const std::vector<BatchRecord>& records) {
    std::map<std::string, RecordEntry> latest;
    for (const auto& record : records)
        for (const auto& entry : record.bakes)
            if (auto [at, fresh] = latest.emplace(entry.name, entry); !fresh && finishedLater(entry, at->second)) at->second = entry;
    return latest;
}

MergedRecord mergeRecords(const std::vector<BatchRecord>& records) {
    MergedRecord merged;
    if (records.empty()) return merged;
    // The latest list's records: an earlier list's lines are another batch.
    const auto newest = std::max_element(records.begin(), records.end(),
                                         [](const auto& a, const auto& b) { return a.started < b.started; });
    std::vector<BatchRecord> current;
    std::copy_if(records.begin(), records.end(), std::back_inserter(current),
                 [&](const auto& record) { return record.listSha256 == newest->listSha256; });
    auto& out = merged.record;
    out.list = newest->list;
    out.listSha256 = newest->listSha256;
    out.lines = newest->lines;
    out.shard = {0, 1};
    out.started = newest->started;
    out.finished = utcNow();
    const auto latest = latestEntries(current);
    for (const auto& [name, entry] : latest) out.bakes.push_back(entry);
    std::sort(out.bakes.begin(), out.bakes.end(), [](const auto& a, const auto& b) { return a.line < b.line; });
    // A run of the whole list covers every part; else each part of the newest split needs a record
    // of its own (a merged record is none: it holds only what the parts it merged did).
    std::vector<const BatchRecord*> runs;
    for (const auto& record : current)
        if (record.merged.empty()) runs.push_back(&record);
    for (const auto* run : runs) out.merged.push_back(run->shard);
    const bool whole = std::any_of(runs.begin(), runs.end(), [](const auto* run) { return run->shard.count == 1; });
    if (!whole && !runs.empty()) {
        const auto* latest = *std::max_element(runs.begin(), runs.end(), [](auto* a, auto* b) { return a->started < b->started; });
        for (uint32_t index = 0; index < latest->shard.count; ++index)
            if (std::none_of(runs.begin(), runs.end(), [&](const auto* run) {
                    return run->shard.index == index && run->shard.count == latest->shard.count;
                }))
                merged.missing.push_back({index, latest->shard.count});
    }
    return merged;
}

bool stillWhole(const RecordEntry& entry, const fs::path& folder) {
    if (entry.files.empty()) return false;
    std::error_code error;
    for (const auto& file : entry.files) {
        const auto path = folder / file.name;
        if (!fs::is_regular_file(path, error) || fs::file_size(path, error) != file.bytes || error) return false;
        try {
            if (cache::sha256OfFile(path) != file.sha256) return false;
        } catch (const std::exception&) {
            return false;
        }
    }
    return true;
}

std::string bakeFingerprint(const std::string& toolVersion, const std::vector<std::string>& words, const std::string& device,
                            const std::vector<fs::path>& inputs) {
    cache::CacheKey key;
    key.add("tool", toolVersion).add("program", cache::programDigest()).add("device", device);
    for (const auto& word : words) key.add("word", word);
    try {
        for (const auto& input : inputs) addInput(key, input);
    } catch (const std::exception&) {
        return {};
    }
    return key.hex();
}

std::string utcNow() {
    timespec now{};
    clock_gettime(CLOCK_REALTIME, &now);
    std::tm utc{};
    gmtime_r(&now.tv_sec, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &utc);
    return fmt::format("{}.{:03}Z", text, now.tv_nsec / 1000000); // to the millisecond: records of one second are ordered
}

} // namespace iblkit::batch
