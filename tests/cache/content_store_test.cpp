// The content store: what is put is got back, a damaged entry (or one moved to another key's
// place) is a miss that is written anew, keys follow every part they are made of, and writers
// racing on one folder never leave half an entry to be read.
#include "cache_error.hpp"
#include "cache_key.hpp"
#include "content_store.hpp"
#include "sha256.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

namespace iblkit::cache {
namespace {

namespace fs = std::filesystem;

TEST(ContentStore, WhatIsPutIsGotBackAndCounted) {
    iblkit::testing::TempFolder folder;
    ContentStore store(folder.path());
    const auto key = CacheKey().add("what", "lut").hex();
    EXPECT_FALSE(store.get(key));
    store.put(key, std::string("\0payload\n", 9));
    EXPECT_EQ(store.get(key), std::string("\0payload\n", 9));
    EXPECT_EQ(store.counts().hits, 1u);
    EXPECT_EQ(store.counts().misses, 1u);
    EXPECT_TRUE(fs::exists(folder.path() / "objects" / key.substr(0, 2) / key));
}

// A payload put in parts is the entry of the whole; read in place it is the same bytes; a peek
// reads without counting (for entries that only save time, not outputs).
TEST(ContentStore, PartsInPlaceAndPeeksAreTheSameEntry) {
    iblkit::testing::TempFolder folder;
    ContentStore store(folder.path());
    const auto whole = CacheKey().add("what", "whole").hex(), inParts = CacheKey().add("what", "parts").hex();
    const std::string text = "{\"name\":\"x\"}\n", floats(4096 * 3 + 7, '\x7f');
    store.put(whole, text + floats);
    const std::array<std::string_view, 2> parts{text, floats};
    store.put(inParts, parts);
    EXPECT_EQ(store.get(inParts), text + floats);
    const auto inPlace = store.getInPlace(whole);
    ASSERT_TRUE(inPlace);
    EXPECT_EQ(inPlace->payload(), text + floats);
    EXPECT_EQ(store.counts().hits, 2u);
    EXPECT_EQ(store.peek(whole), text + floats);
    EXPECT_FALSE(store.peek(CacheKey().add("what", "absent").hex()));
    EXPECT_EQ(store.counts().hits, 2u) << "peeks are not counted";
    EXPECT_EQ(store.counts().misses, 0u);
    EXPECT_FALSE(store.getInPlace(CacheKey().add("what", "absent").hex()));
    EXPECT_EQ(store.counts().misses, 1u);
}

TEST(ContentStore, ADamagedEntryIsAMissAndIsRemoved) {
    iblkit::testing::TempFolder folder;
    ContentStore store(folder.path());
    const auto key = CacheKey().add("what", "specular").hex();
    store.put(key, std::string(1000, 'x'));
    const auto path = folder.path() / "objects" / key.substr(0, 2) / key;
    {
        std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(500);
        file.put('y'); // one byte of the payload changed on disk
    }
    EXPECT_FALSE(store.get(key));
    EXPECT_EQ(store.counts().corrupt, 1u);
    EXPECT_FALSE(fs::exists(path));
    store.put(key, "whole");
    fs::resize_file(path, 20); // cut short
    EXPECT_FALSE(store.get(key));
    EXPECT_EQ(store.counts().corrupt, 2u);
}

TEST(ContentStore, AnEntryCopiedOrRenamedToAnotherKeysPlaceIsDamaged) {
    iblkit::testing::TempFolder folder;
    ContentStore store(folder.path());
    const auto one = CacheKey().add("what", "one").hex(), two = CacheKey().add("what", "two").hex();
    const auto three = CacheKey().add("what", "three").hex();
    const auto pathOf = [&](const std::string& key) { return folder.path() / "objects" / key.substr(0, 2) / key; };
    store.put(one, "the first value");
    store.put(two, "the second value");
    fs::copy_file(pathOf(one), pathOf(two), fs::copy_options::overwrite_existing);
    EXPECT_FALSE(store.get(two));
    EXPECT_EQ(store.counts().corrupt, 1u);
    EXPECT_EQ(store.get(one), "the first value");
    fs::create_directories(pathOf(three).parent_path());
    fs::rename(pathOf(one), pathOf(three));
    EXPECT_FALSE(store.get(three));
    EXPECT_EQ(store.counts().corrupt, 2u);
    EXPECT_FALSE(fs::exists(pathOf(three)));
}

// The first format held no key: its entries are misses, replaced, and not called damaged.
TEST(ContentStore, AnEntryOfTheEarlierFormatIsAMissNotDamage) {
    iblkit::testing::TempFolder folder;
    ContentStore store(folder.path());
    const auto key = CacheKey().add("what", "lut").hex();
    const auto path = folder.path() / "objects" / key.substr(0, 2) / key;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << "IBLKCAS1" << sha256Hex("payload") << '\n' << "payload";
    EXPECT_FALSE(store.get(key));
    EXPECT_EQ(store.counts().corrupt, 0u);
    EXPECT_EQ(store.counts().misses, 1u);
    EXPECT_FALSE(fs::exists(path));
}

TEST(CacheKey, EveryPartAndItsLabelCount) {
    const auto base = CacheKey().add("a", "bc").add("n", uint64_t{7}).hex();
    EXPECT_EQ(base, CacheKey().add("a", "bc").add("n", uint64_t{7}).hex());
    EXPECT_NE(base, CacheKey().add("a", "b").add("cn", uint64_t{7}).hex()) << "no collision by concatenation";
    EXPECT_NE(base, CacheKey().add("a", "bc").add("n", uint64_t{8}).hex());
    EXPECT_NE(base, CacheKey().add("b", "bc").add("n", uint64_t{7}).hex());
    EXPECT_NE(CacheKey().add("mips", std::vector<bool>{true, false}).hex(),
              CacheKey().add("mips", std::vector<bool>{false, true}).hex());
}

TEST(ContentStore, WritersRacingOnOneFolderLeaveOnlyWholeEntries) {
    iblkit::testing::TempFolder folder;
    const auto key = CacheKey().add("what", "shared").hex();
    const std::string payload(1 << 20, 'p');
    std::vector<std::thread> writers;
    std::atomic<int> halfSeen{0};
    for (int t = 0; t < 4; ++t)
        writers.emplace_back([&] {
            ContentStore store(folder.path());
            for (int i = 0; i < 20; ++i) {
                store.put(key, payload);
                const auto got = store.get(key);
                if (!got || *got != payload) ++halfSeen;
            }
        });
    for (auto& writer : writers) writer.join();
    EXPECT_EQ(halfSeen, 0);
    size_t leftovers = 0;
    for (const auto& entry : fs::recursive_directory_iterator(folder.path()))
        if (entry.path().filename().string().find(".tmp-") != std::string::npos) ++leftovers;
    EXPECT_EQ(leftovers, 0u) << "no temporary is left behind";
}

// What killed writers leave is removed by a later put into the same folder; a live writer's is not.
TEST(ContentStore, APutRemovesTheTemporariesOfWritersThatAreGone) {
    iblkit::testing::TempFolder folder;
    const auto key = CacheKey().add("what", "left behind").hex();
    ContentStore store(folder.path());
    store.put(key, "first");
    const auto place = folder.path() / "objects" / key.substr(0, 2);
    char host[256] = {};
    gethostname(host, sizeof host - 1);
    const pid_t child = fork(); // a process id that is surely gone once reaped
    if (child == 0) _exit(0);
    waitpid(child, nullptr, 0);
    const auto temporary = [&](const std::string& owner) {
        const auto path = place / (key + ".tmp-" + owner + "-aB3xYz");
        std::ofstream(path) << "half an entry";
        return path;
    };
    const auto gone = temporary(std::string(host) + "-" + std::to_string(child));
    const auto live = temporary(std::string(host) + "-" + std::to_string(getpid()));
    const auto elsewhere = temporary("another-host-12");
    store.put(key, "second");
    EXPECT_FALSE(fs::exists(gone)) << "its writer is gone";
    EXPECT_TRUE(fs::exists(live)) << "its writer still runs";
    EXPECT_TRUE(fs::exists(elsewhere)) << "another machine's writer may still run";
    fs::last_write_time(elsewhere, fs::file_time_type::clock::now() - std::chrono::hours(25));
    store.put(key, "third");
    EXPECT_FALSE(fs::exists(elsewhere)) << "a day old: no writer takes that long";
    EXPECT_TRUE(fs::exists(live));
    EXPECT_EQ(store.get(key), "third");
}

TEST(ContentStore, AFolderItCannotWriteIsOneError) {
    iblkit::testing::TempFolder folder;
    std::ofstream(folder.path() / "file") << "not a folder";
    ContentStore store(folder.path() / "file");
    try {
        store.put(CacheKey().add("a", "b").hex(), "x");
        ADD_FAILURE() << "no error";
    } catch (const CacheError& error) {
        EXPECT_NE(std::string(error.what()).find("cannot make the cache folder"), std::string::npos) << error.what();
    }
}

} // namespace
} // namespace iblkit::cache
