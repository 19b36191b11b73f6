// A batch's records: written and read back, merged into the whole status (the latest entry of each
// line wins; a part without a record is named), and a line's fingerprint and files checked.
#include "batch_record.hpp"
#include "sha256.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace iblkit::batch {
namespace {

namespace fs = std::filesystem;

RecordEntry entry(const std::string& name, size_t line, const std::string& status, const std::string& finished) {
    RecordEntry entry;
    entry.name = name;
    entry.line = line;
    entry.status = status;
    entry.finished = finished;
    return entry;
}

BatchRecord part(uint32_t index, uint32_t count, std::vector<RecordEntry> bakes, const std::string& started = "2026-01-01") {
    return {"list.txt", "abc", 4, {index, count}, {}, started, started, std::move(bakes)};
}

TEST(BatchRecord, WrittenAndReadBack) {
    iblkit::testing::TempFolder folder;
    auto record = part(1, 3, {entry("b", 3, "failed", "2026-01-01T00:00:01.000Z")});
    record.bakes[0].error = "b.exr: no such file";
    record.bakes[0].files = {{"manifest.json", "00ff", 12}};
    record.bakes[0].steps = {{"prefilter", 1.5, 2.5}};
    writeRecord(recordPath(folder.path(), record.shard), record);
    EXPECT_TRUE(fs::exists(folder.path() / "batch-shards" / "1-of-3.json"));
    const auto records = readRecords(folder.path());
    ASSERT_EQ(records.size(), 1u);
    EXPECT_EQ(recordText(records[0]), recordText(record));
    EXPECT_EQ(recordPath(folder.path(), {0, 1}), folder.path() / "batch.json");
}

TEST(BatchRecord, AFileThatIsNoRecordIsNamedAndLeftOut) {
    iblkit::testing::TempFolder folder;
    fs::create_directories(folder.path() / "batch-shards");
    std::ofstream(folder.path() / "batch-shards" / "0-of-2.json") << "{ not json";
    std::vector<std::string> unreadable;
    EXPECT_TRUE(readRecords(folder.path(), &unreadable).empty());
    EXPECT_EQ(unreadable.size(), 1u);
}

TEST(BatchRecord, TheMergeTakesEachLinesLatestEntryAndNamesMissingParts) {
    const auto merged = mergeRecords({part(0, 3, {entry("a", 1, "failed", "2026-01-01T10:00:00.000Z"), entry("d", 4, "pending", "")}),
                                      part(2, 3, {entry("c", 3, "baked", "2026-01-01T10:00:00.000Z")}),
                                      part(0, 3, {entry("a", 1, "baked", "2026-01-01T11:00:00.000Z")}, "2026-01-02")});
    ASSERT_EQ(merged.record.bakes.size(), 3u);
    EXPECT_EQ(merged.record.bakes[0].name, "a");
    EXPECT_EQ(merged.record.bakes[0].status, "baked") << "the later entry wins";
    EXPECT_EQ(merged.record.bakes[1].name, "c");
    EXPECT_EQ(merged.record.bakes[2].status, "pending");
    ASSERT_EQ(merged.missing.size(), 1u);
    EXPECT_EQ(merged.missing[0].index, 1u);
    // A merged record holds only what its parts did: merging it again still names the missing part.
    const auto again = mergeRecords({merged.record, part(0, 3, {})});
    EXPECT_EQ(again.missing.size(), 2u);
    // A run of the whole list covers every part.
    EXPECT_TRUE(mergeRecords({part(0, 3, {}), part(0, 1, {})}).missing.empty());
}

TEST(BatchRecord, AnEntryIsWholeOnlyWhileEveryFileIsAsRecorded) {
    iblkit::testing::TempFolder folder;
    std::ofstream(folder.path() / "manifest.json") << "{}";
    auto done = entry("a", 1, "baked", "t");
    done.files = {{"manifest.json", cache::sha256OfFile(folder.path() / "manifest.json"), 2}};
    EXPECT_TRUE(stillWhole(done, folder.path()));
    std::ofstream(folder.path() / "manifest.json") << "[]"; // same size, other bytes
    EXPECT_FALSE(stillWhole(done, folder.path()));
    fs::remove(folder.path() / "manifest.json");
    EXPECT_FALSE(stillWhole(done, folder.path()));
    EXPECT_FALSE(stillWhole(entry("a", 1, "baked", "t"), folder.path())) << "an entry without files is not done";
}

TEST(BatchRecord, TheFingerprintFollowsTheWordsTheDeviceAndTheInputsBytes) {
    iblkit::testing::TempFolder folder;
    const auto input = folder.path() / "env.hdr";
    std::ofstream(input) << "one";
    const auto first = bakeFingerprint("1.0", {"env.hdr", "--size", "16"}, "", {input});
    EXPECT_EQ(first, bakeFingerprint("1.0", {"env.hdr", "--size", "16"}, "", {input}));
    EXPECT_NE(first, bakeFingerprint("1.0", {"env.hdr", "--size", "32"}, "", {input}));
    EXPECT_NE(first, bakeFingerprint("1.0", {"env.hdr", "--size", "16"}, "gpu", {input}));
    EXPECT_NE(first, bakeFingerprint("1.1", {"env.hdr", "--size", "16"}, "", {input}));
    std::ofstream(input) << "two";
    EXPECT_NE(first, bakeFingerprint("1.0", {"env.hdr", "--size", "16"}, "", {input}));
    EXPECT_EQ(bakeFingerprint("1.0", {}, "", {folder.path() / "missing.hdr"}), "") << "an unreadable input is never done";
}

} // namespace
} // namespace iblkit::batch
