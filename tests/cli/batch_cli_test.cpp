// `iblkit batch` as a user runs it: each line's folder is what `iblkit bake` writes for it, a second
// run bakes nothing that is done and whole, a bad line is refused before any work, a failed bake
// does not stop the others, parts come from the flag or the scheduler and merge into one status,
// and a cache shared by concurrent bakers killed at random never serves a wrong entry.
#include "bake_cli_fixture.hpp"

#include "content_store.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <thread>

namespace iblkit::testing {
namespace {

namespace fs = std::filesystem;

const char* const kSmall = "--size 16 --samples 16 --lut-size 8 --lut-samples 16 --irradiance-size 4";

class BatchCli : public BakeCli {
protected:
    std::string list(const std::string& text) const { return scratch.write("list.txt", text).string(); }
    ProcessResult batch(std::vector<std::string> arguments, std::vector<std::string> environment = {}) const {
        arguments.insert(arguments.begin(), {IBLKIT_EXECUTABLE, "batch"});
        environment.push_back("XDG_CACHE_HOME=" + cache.path().string());
        return runProcess(arguments, environment);
    }
    std::map<std::string, std::string> statuses(const std::string& folder = "out") const {
        const auto record = nlohmann::json::parse(readFile(fs::path(at(folder)) / "batch.json"));
        std::map<std::string, std::string> status;
        for (const auto& bake : record["bakes"]) status[bake["name"]] = bake["status"];
        return status;
    }
    // The folder `iblkit bake WORDS -o local/NAME` writes.
    std::map<std::string, std::string> baked(const std::string& name, const std::string& words) const {
        std::vector<std::string> arguments{"bake"};
        std::istringstream split(words);
        for (std::string word; split >> word;) arguments.push_back(word);
        arguments.insert(arguments.end(), {"-o", at("local/" + name), "--no-cache", "--quiet"});
        const auto result = iblkit(arguments);
        EXPECT_EQ(result.exitCode, 0) << result.err;
        return snapshot(at("local/" + name));
    }
};

TEST_F(BatchCli, EachLineIsTheFolderBakeWritesForIt) {
    scratch.write("warm.hdr", radianceHdr(8, 4, 129));
    const std::map<std::string, std::string> lines{
        {"sky", kSmall},
        {"three", std::string(kSmall) + " --profile threejs"},
        // The LUT of the same settings in the other file format: a batch makes the LUT once.
        {"rg32", std::string(kSmall) + " --lut-format rg32f"},
        {"warm", at("warm.hdr") + " " + kSmall + " --dds"}};
    std::string text = "# the kit's batch test\n";
    for (const auto& [name, words] : lines) text += name + " " + words + "\n";
    const auto result = batch({list(text), "-o", at("out"), "--no-cache", "--quiet"});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    for (const auto& [name, words] : lines) EXPECT_EQ(snapshot(at("out/" + name)), baked(name, words)) << name;
    EXPECT_EQ(statuses(), (std::map<std::string, std::string>{{"rg32", "baked"}, {"sky", "baked"}, {"three", "baked"}, {"warm", "baked"}}));
}

TEST_F(BatchCli, ASecondRunBakesOnlyWhatIsNotDoneAndWhole) {
    scratch.write("a.hdr", radianceHdr(8, 4, 129));
    const auto path = list(fmt::format("a {} {}\nb {}\nc {} --profile babylon\n", at("a.hdr"), kSmall, kSmall, kSmall));
    ASSERT_EQ(batch({path, "-o", at("out"), "--quiet"}).exitCode, 0);
    const auto before = snapshot(at("out/b"));
    const auto again = batch({path, "-o", at("out")});
    EXPECT_EQ(again.exitCode, 0) << again.err;
    EXPECT_NE(again.err.find("0 baked, 3 done already"), std::string::npos) << again.err;
    EXPECT_EQ(snapshot(at("out/b")), before);
    // The input's bytes change: that line is baked again. A file of another bake changed: that line
    // is not done, and its folder, which may hold someone's edit, is not replaced (as by iblkit bake).
    scratch.write("a.hdr", radianceHdr(8, 4, 130));
    std::ofstream(at("out/c/preview.png"), std::ios::app) << "x";
    const auto third = batch({path, "-o", at("out")});
    EXPECT_EQ(third.exitCode, 1) << third.err;
    EXPECT_NE(third.err.find("c (line 3): refusing to replace"), std::string::npos) << third.err;
    EXPECT_EQ(statuses(), (std::map<std::string, std::string>{{"a", "baked"}, {"b", "done"}, {"c", "failed"}}));
    fs::remove_all(at("out/c"));
    EXPECT_EQ(batch({path, "-o", at("out"), "--quiet"}).exitCode, 0);
    EXPECT_EQ(statuses(), (std::map<std::string, std::string>{{"a", "done"}, {"b", "done"}, {"c", "baked"}}));
    EXPECT_EQ(batch({path, "-o", at("out"), "--force", "--quiet"}).exitCode, 0);
    EXPECT_EQ(statuses()["b"], "baked") << "--force bakes every line";
}

TEST_F(BatchCli, ABadLineIsRefusedBeforeAnyWorkWithItsNumber) {
    for (const auto& [line, expected] : std::vector<std::pair<std::string, std::string>>{
             {"c --size 3", "list.txt:4: error: --size 3 is not a power of two"},
             {"c --bogus", "list.txt:4: error: The following argument was not expected: --bogus"},
             {"c --cache x", "list.txt:4: error: --cache is a flag of the batch, not of a line"},
             {"c " + at("missing.exr"), "list.txt:4: error: ENV " + at("missing.exr") + ": no such file or folder"},
             {"a", "list.txt:4: error: 'a' is named on line 2 already"},
             {"c 'open", "list.txt:4: error: the quote ' is not closed"}}) {
        const auto path = list(fmt::format("# header\na {}\nb {}\n{}\n", kSmall, kSmall, line));
        const auto result = batch({path, "-o", at("out")});
        EXPECT_EQ(result.exitCode, 1) << line;
        EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_FALSE(fs::exists(at("out"))) << "nothing is made for a refused list";
    }
}

TEST_F(BatchCli, AFailedBakeIsReportedAndTheRestGoOn) {
    scratch.write("broken.hdr", "not an image");
    const auto path = list(fmt::format("a {}\nbroken {} {}\nc {}\n", kSmall, at("broken.hdr"), kSmall, kSmall));
    const auto result = batch({path, "-o", at("out"), "--quiet"});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.err.find("broken (line 2): '" + at("broken.hdr") + "' is not a Radiance HDR image"), std::string::npos)
        << result.err;
    EXPECT_EQ(statuses(), (std::map<std::string, std::string>{{"a", "baked"}, {"broken", "failed"}, {"c", "baked"}}));
    EXPECT_FALSE(fs::exists(at("out/broken")));
}

TEST_F(BatchCli, PartsFromTheFlagAndTheSchedulerMergeIntoTheWholeStatus) {
    const auto path = list(fmt::format("a {}\nb {}\nc {}\n", kSmall, kSmall, kSmall));
    ASSERT_EQ(batch({path, "-o", at("out"), "--shard", "0/2", "--quiet"}).exitCode, 0);
    EXPECT_TRUE(fs::exists(at("out/a")) && fs::exists(at("out/c")) && !fs::exists(at("out/b")));
    const auto partial = batch({"--merge", at("out")});
    EXPECT_EQ(partial.exitCode, 1) << "a part has no record yet";
    EXPECT_NE(partial.err.find("part 1 of 2: no record"), std::string::npos) << partial.err;
    const auto slurm = batch({path, "-o", at("out"), "--quiet"},
                             {"SLURM_ARRAY_TASK_ID=4", "SLURM_ARRAY_TASK_MIN=3", "SLURM_ARRAY_TASK_COUNT=2"});
    ASSERT_EQ(slurm.exitCode, 0) << slurm.err;
    EXPECT_TRUE(fs::exists(at("out/batch-shards/1-of-2.json")));
    const auto merged = batch({"--merge", at("out")});
    EXPECT_EQ(merged.exitCode, 0) << merged.err;
    EXPECT_EQ(statuses(), (std::map<std::string, std::string>{{"a", "baked"}, {"b", "baked"}, {"c", "baked"}}));
    // The next run of the whole list finds every part done.
    const auto whole = batch({path, "-o", at("out")});
    EXPECT_NE(whole.err.find("0 baked, 3 done already"), std::string::npos) << whole.err;
    EXPECT_NE(batch({path, "-o", at("out")}, {"JOB_COMPLETION_INDEX=0"}).err.find("--shards N"), std::string::npos);
}

TEST_F(BatchCli, TheSlurmScriptIsAnArrayOfThisBatchOnASharedCache) {
    const auto path = list(fmt::format("a {}\nb {}\nc {}\n", kSmall, kSmall, kSmall));
    const auto result = batch({path, "-o", at("out"), "--cache", at("shared"), "--shards", "2", "--slurm-script"});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_TRUE(result.out.starts_with("#!/bin/sh\n")) << result.out;
    EXPECT_NE(result.out.find("#SBATCH --array=0-1\n"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find(fmt::format("batch {} -o {} --cache {} --quiet\n", path, at("out"), at("shared"))),
              std::string::npos)
        << result.out;
    EXPECT_NE(result.out.find("#SBATCH --chdir=" + fs::current_path().string() + "\n"), std::string::npos)
        << "the tasks read the list's relative paths from here";
    EXPECT_TRUE(fs::is_directory(at("out/batch-shards"))) << "each task's log goes there";
    EXPECT_NE(batch({path, "-o", at("out"), "--shards", "4", "--slurm-script"}).exitCode, 0) << "more parts than lines";
}

// The words of a small bake of `environment`, of one of three kinds that make different entries.
std::vector<std::string> smallBakeWords(const std::string& environment, size_t kind) {
    std::vector<std::string> words{environment, "--size", "16", "--lut-size", "8", "--lut-samples", "16", "--irradiance-size", "4"};
    if (kind == 2) words.insert(words.end(), {"--method", "pyramid"});
    else words.insert(words.end(), {"--samples", "16"});
    if (kind == 1) words.insert(words.end(), {"--profile", "threejs"});
    return words;
}

// Bakers sharing one cache, each killed at a random moment or left to finish, in rounds: each
// round bakes a new environment (entries are written) beside the last one's (entries are read).
// Every entry left in the cache is whole, and a bake from it is byte for byte a bake without one.
// $IBLKIT_CACHE_STRESS_ROUNDS runs more rounds than the suite's three (docs/batch.md quotes a long run).
int stressRounds() {
    const char* rounds = std::getenv("IBLKIT_CACHE_STRESS_ROUNDS");
    return rounds && std::atoi(rounds) > 0 ? std::atoi(rounds) : 3;
}

TEST_F(BatchCli, ConcurrentBakersKilledAtRandomNeverLeaveAWrongEntry) {
    const auto environment = [&](int round) { return at(fmt::format("env{}.hdr", round)); };
    std::mt19937 random(20261129);
    std::uniform_real_distribution<double> killAfter(0.02, 0.8); // a small bake takes 0.3-1 s with six at once
    size_t killed = 0, finished = 0;
    const int rounds = stressRounds();
    for (int round = 0; round < rounds; ++round) {
        scratch.write(fmt::format("env{}.hdr", round), radianceHdr(8, 4, static_cast<unsigned char>(100 + round % 60)));
        std::vector<std::thread> bakers;
        std::vector<ProcessResult> results(6);
        for (size_t i = 0; i < results.size(); ++i) {
            const double kill = i % 3 == 2 ? 0 : killAfter(random); // a third run to the end
            auto arguments = smallBakeWords(environment(i < 4 || round == 0 ? round : round - 1), i % 3);
            arguments.insert(arguments.begin(), "bake");
            arguments.insert(arguments.end(), {"-o", at(fmt::format("r{}-{}", round, i)), "--cache", at("shared"), "--quiet"});
            bakers.emplace_back([&, arguments, kill, i] { results[i] = iblkit(arguments, kill); });
        }
        for (auto& baker : bakers) baker.join();
        for (const auto& result : results) (result.exitCode == 0 ? finished : killed) += 1;
    }
    EXPECT_GT(killed, 0u);
    EXPECT_GT(finished, 0u);
    std::printf("%zu bakers killed, %zu finished, in %d rounds\n", killed, finished, rounds);
    // Every entry is whole: read through the store, none is damaged.
    cache::ContentStore store(at("shared"), cache::ContentStore::Access::ReadOnly);
    size_t entries = 0, temporaries = 0;
    for (const auto& item : fs::recursive_directory_iterator(at("shared") + "/objects")) {
        if (!item.is_regular_file()) continue;
        if (item.path().filename().string().find(".tmp-") != std::string::npos) {
            ++temporaries;
            continue;
        }
        ++entries;
        EXPECT_TRUE(store.get(item.path().filename().string())) << item.path();
    }
    EXPECT_EQ(store.counts().corrupt, 0u);
    EXPECT_GT(entries, 0u);
    std::printf("%zu entries, all whole; %zu temporaries left by killed bakers\n", entries, temporaries);
    // And what a bake takes from it is what a bake without a cache makes.
    for (const int round : {0, rounds - 1})
        for (size_t kind = 0; kind < 3; ++kind) {
            auto arguments = smallBakeWords(environment(round), kind);
            std::string words;
            for (const auto& word : arguments) words += (words.empty() ? "" : " ") + word;
            arguments.insert(arguments.begin(), "bake");
            const auto folder = at(fmt::format("cached{}-{}", round, kind));
            arguments.insert(arguments.end(), {"-o", folder, "--cache", at("shared"), "--quiet"});
            ASSERT_EQ(iblkit(arguments).exitCode, 0);
            EXPECT_EQ(snapshot(folder), baked(fmt::format("v{}-{}", round, kind), words)) << words;
        }
}

} // namespace
} // namespace iblkit::testing
