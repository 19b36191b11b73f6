#include "batch_bench.hpp"

#include "bench_error.hpp"
#include "measurements.hpp"
#include "scratch_folder.hpp"
#include "this_program.hpp"
#include "timed_process.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <set>

namespace iblkit::bench {
namespace {

namespace fs = std::filesystem;

struct Line {
    std::string name;
    fs::path input; // empty: the built-in sky
};

std::string fileBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool sameFiles(const fs::path& a, const fs::path& b) {
    std::set<fs::path> names;
    for (const auto* folder : {&a, &b})
        for (const auto& item : fs::recursive_directory_iterator(*folder))
            if (item.is_regular_file()) names.insert(fs::relative(item.path(), *folder));
    return std::all_of(names.begin(), names.end(), [&](const fs::path& name) {
        return fs::exists(a / name) && fs::exists(b / name) && fileBytes(a / name) == fileBytes(b / name);
    });
}

// The environment-dependent device steps of every bake in a batch's record.
double environmentWork(const fs::path& record) {
    static const std::set<std::string> steps{"source cube", "lights", "irradiance", "prefilter", "preview"};
    const auto json = nlohmann::json::parse(fileBytes(record), nullptr, false);
    if (json.is_discarded() || !json.contains("bakes")) throw BenchError("the batch's record does not parse: " + record.string());
    double milliseconds = 0;
    for (const auto& bake : json["bakes"])
        for (const auto& step : bake.value("steps", nlohmann::json::array()))
            if (steps.count(step.value("name", ""))) milliseconds += step.value("wall_ms", 0.0);
    return milliseconds;
}

class BatchPairs {
public:
    BatchPairs(const BenchOptions& options, std::vector<Line> lines)
        : options_(options), lines_(std::move(lines)), scratch_("bench-batch"), program_(files::thisProgram()) {
        std::ofstream list(scratch_.path() / "list.txt");
        for (const auto& line : lines_) list << line.name << ' ' << line.input.string() << '\n';
    }

    BatchTiming measure(bool withCache) {
        BatchTiming timing{withCache ? "fresh cache" : "no cache", uint32_t(lines_.size()), 0, 0, 0, 0, 0, 0, options_.repeat};
        std::vector<double> separate, batch, ratios, environment;
        for (uint32_t pair = 0; pair <= options_.repeat; ++pair) { // pair 0 warms up (Mesa's shader cache, the page cache)
            double separateMs = 0, batchMs = 0;
            const auto runSeparate = [&] { separateMs = separateBakes(withCache); };
            const auto runBatch = [&] { batchMs = oneBatch(withCache); };
            if (pair % 2) runSeparate(), runBatch();
            else runBatch(), runSeparate();
            if (pair == 0) {
                for (const auto& line : lines_)
                    if (!sameFiles(scratch_.path() / "separate" / line.name, scratch_.path() / "batch" / line.name))
                        throw BenchError(fmt::format("the batch's {} is not what iblkit bake writes for it", line.name));
                continue;
            }
            separate.push_back(separateMs);
            batch.push_back(batchMs);
            ratios.push_back(batchMs / separateMs);
            environment.push_back(environmentWork(scratch_.path() / "batch" / "batch.json"));
            log(fmt::format("batch of {} ({}): {:.2f} s against {:.2f} s separately ({:.3f})", lines_.size(), timing.cache,
                            batchMs / 1e3, separateMs / 1e3, ratios.back()));
        }
        timing.separateMilliseconds = median(separate);
        timing.batchMilliseconds = median(batch);
        timing.ratio = median(ratios);
        timing.ratioMin = *std::min_element(ratios.begin(), ratios.end());
        timing.ratioMax = *std::max_element(ratios.begin(), ratios.end());
        timing.environmentMilliseconds = median(environment);
        return timing;
    }

private:
    std::vector<std::string> cacheArguments(bool withCache, const std::string& side) {
        const auto cache = scratch_.path() / ("cache-" + side);
        fs::remove_all(cache); // a fresh one each time, as a first bake finds it
        return withCache ? std::vector<std::string>{"--cache", cache.string()} : std::vector<std::string>{"--no-cache"};
    }

    double separateBakes(bool withCache) {
        const auto folder = scratch_.path() / "separate";
        fs::remove_all(folder);
        double total = 0;
        const auto cache = cacheArguments(withCache, "separate");
        for (const auto& line : lines_) {
            std::vector<std::string> arguments{program_.string(), "bake"};
            if (!line.input.empty()) arguments.push_back(line.input.string());
            arguments.insert(arguments.end(), {"-o", (folder / line.name).string(), "--quiet"});
            arguments.insert(arguments.end(), cache.begin(), cache.end());
            total += runTimed(arguments, scratch_.path() / "bake.out", scratch_.path() / "bake.log", "bake " + line.name);
        }
        return total;
    }

    double oneBatch(bool withCache) {
        const auto folder = scratch_.path() / "batch";
        fs::remove_all(folder);
        std::vector<std::string> arguments{program_.string(), "batch", (scratch_.path() / "list.txt").string(), "-o",
                                           folder.string(), "--quiet"};
        const auto cache = cacheArguments(withCache, "batch");
        arguments.insert(arguments.end(), cache.begin(), cache.end());
        return runTimed(arguments, scratch_.path() / "batch.out", scratch_.path() / "batch.log", "batch");
    }

    void log(const std::string& line) const {
        if (!options_.log) return;
        fmt::print(options_.log, "bench  {}\n", line);
        std::fflush(options_.log);
    }

    const BenchOptions& options_;
    std::vector<Line> lines_;
    files::ScratchFolder scratch_;
    fs::path program_;
};

} // namespace

std::vector<BatchTiming> benchBatch(const BenchOptions& options, const std::vector<std::string>& environments,
                                    const fs::path& cacheDir) {
    std::vector<Line> lines;
    for (const auto& name : environments)
        if (const auto input = bakeInputOf(name, cacheDir)) {
            // A file's line is named by its stem, in the characters a batch's names take.
            std::string line = name == "sky" || isBlenderWorld(name) ? name : fs::path(name).stem().string();
            std::replace_if(line.begin(), line.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '-');
            lines.push_back({line, *input});
        }
    if (lines.size() < 2) throw BenchError("--outputs batch needs two or more environments the bake can read (sky, blender, files)");
    BatchPairs pairs(options, std::move(lines));
    return {pairs.measure(true), pairs.measure(false)};
}

} // namespace iblkit::bench
