#include "bake_bench.hpp"

#include "bake.hpp"
#include "bake_plan.hpp"
#include "bench_error.hpp"
#include "bench_scenes.hpp"
#include "ktx2.hpp"
#include "scene_materials.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <unistd.h>

namespace iblkit::bench {
namespace {

namespace fs = std::filesystem;

// MESA_SHADER_CACHE_DIR at `folder` while it lives: Mesa reads it whenever a device is made, so a
// bake made meanwhile starts with an empty shader cache, as on a fresh machine.
class MesaShaderCacheAt {
public:
    explicit MesaShaderCacheAt(const fs::path& folder) {
        if (const char* value = std::getenv(kVariable)) previous_ = value;
        setenv(kVariable, folder.c_str(), 1);
    }
    ~MesaShaderCacheAt() {
        if (previous_) setenv(kVariable, previous_->c_str(), 1);
        else unsetenv(kVariable);
    }
    MesaShaderCacheAt(const MesaShaderCacheAt&) = delete;
    MesaShaderCacheAt& operator=(const MesaShaderCacheAt&) = delete;

private:
    static constexpr const char* kVariable = "MESA_SHADER_CACHE_DIR";
    std::optional<std::string> previous_;
};

struct Bake {
    std::string label;
    std::string environment;
    std::optional<fs::path> file, scene, cache; // no file: the built-in sky
};

std::string mipList(const std::vector<bool>& prefiltered) {
    std::vector<uint32_t> mips;
    for (uint32_t mip = 1; mip < prefiltered.size(); ++mip)
        if (prefiltered[mip]) mips.push_back(mip);
    if (mips.empty()) return "none";
    const bool contiguous = mips.back() - mips.front() + 1 == mips.size();
    if (contiguous) return mips.size() == 1 ? std::to_string(mips[0]) : fmt::format("{}-{}", mips.front(), mips.back());
    std::string text;
    for (const auto mip : mips) text += (text.empty() ? "" : ", ") + std::to_string(mip);
    return text;
}

// What the device computed, from the bake's steps and its plan.
std::string computedBy(const bake::BakeSummary& summary, const bake::BakePlan& plan) {
    std::string text;
    for (const auto& step : summary.steps) {
        if (step.name == "load" || step.name == "cache" || step.name == "device" || step.name == "outputs" ||
            step.name == "tear-down" || step.name == "write")
            continue;
        std::string part = step.name;
        if (step.name == "prefilter") part = "prefilter mips " + mipList(plan.prefilteredMips());
        if (step.name == "irradiance" && !plan.irradiance) part = "SH (the preview's exposure)";
        if (part != "prefilter mips none") text += (text.empty() ? "" : ", ") + part;
    }
    return text.empty() ? "nothing" : text;
}

image_io::Texture readKtx2(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), {}};
    if (!in && !in.eof()) throw BenchError(path.string() + ": cannot read a bake's file back");
    return image_io::decodeKtx2(std::as_bytes(std::span(bytes.data(), bytes.size())), path.string());
}

class BakeBench {
public:
    BakeBench(const BenchOptions& options, fs::path scratch) : options_(options), scratch_(std::move(scratch)) {}

    // Bakes into a fresh folder; returns the bake's wall time. A full bake's folder is kept for the
    // others of its environment to be compared with.
    void run(const Bake& bake) {
        bake::BakeSettings settings;
        settings.environment = bake.file;
        settings.scene = bake.scene;
        settings.cache = bake.cache;
        settings.context = options_.context;
        settings.outputDir = scratch_ / fmt::format("bake-{}", count_++);
        bake::BakeProgress quiet(true);
        const auto summary = bake::bakeEnvironment(settings, "bench", quiet);
        const auto scene = bake.scene ? std::optional(scene::readSceneMaterials(*bake.scene)) : std::nullopt;
        const auto plan = bake::planBake(bake::resolveSettings(settings), scene);
        auto& timing = timingOf(bake);
        timing.computed = computedBy(summary, plan);
        times_[timing.bake + "/" + timing.environment].push_back(summary.wallMilliseconds);
        if (bake.label == kFull) {
            fs::remove_all(fullFolder_[bake.environment]);
            fullFolder_[bake.environment] = settings.outputDir;
            return;
        }
        const auto& full = fullFolder_.at(bake.environment);
        const std::vector<bool> all;
        timing.identical = timing.identical && neededLevelsMatch(full, settings.outputDir, "specular.ktx2", plan.prefilteredMips()) &&
                           neededLevelsMatch(full, settings.outputDir, "brdf_lut.ktx2", all) &&
                           neededLevelsMatch(full, settings.outputDir, "irradiance.ktx2", all);
        fs::remove_all(settings.outputDir);
    }

    std::vector<BakeTiming> timings() const {
        auto rows = rows_;
        for (auto& row : rows) {
            row.wallMilliseconds = medianOf(row.bake, row.environment);
            row.fullWallMilliseconds = medianOf(kFull, row.environment);
            row.repeat = uint32_t(times_.at(row.bake + "/" + row.environment).size());
        }
        return rows;
    }

    static constexpr const char* kFull = "full, no cache";

private:
    BakeTiming& timingOf(const Bake& bake) {
        for (auto& row : rows_)
            if (row.bake == bake.label && row.environment == bake.environment) return row;
        rows_.push_back({bake.label, bake.environment, {}, 0, 0, 0, true});
        return rows_.back();
    }
    double medianOf(const std::string& label, const std::string& environment) const {
        auto times = times_.at(label + "/" + environment);
        std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
        return times[times.size() / 2];
    }

    const BenchOptions& options_;
    fs::path scratch_;
    uint32_t count_ = 0;
    std::vector<BakeTiming> rows_;
    std::map<std::string, std::vector<double>> times_;
    std::map<std::string, fs::path> fullFolder_;
};

std::vector<std::string> blenderWorldsAmong(const std::vector<BenchEnvironment>& environments) {
    std::vector<std::string> worlds;
    for (const auto& environment : environments)
        if (isBlenderWorld(environment.name)) worlds.push_back(environment.name);
    return worlds;
}

void logBake(const BenchOptions& options, const std::string& what) {
    if (!options.log) return;
    fmt::print(options.log, "bench  bake {}\n", what);
    std::fflush(options.log);
}

} // namespace

bool neededLevelsMatch(const fs::path& full, const fs::path& baked, const std::string& name, const std::vector<bool>& needed) {
    if (!fs::exists(baked / name)) return true; // skipped: nothing to compare
    const auto mine = readKtx2(baked / name), theirs = readKtx2(full / name);
    if (mine.format != theirs.format || mine.mips != theirs.mips || mine.width != theirs.width || mine.faces != theirs.faces)
        return false;
    for (uint32_t mip = 0; mip < mine.mips; ++mip)
        if ((mip >= needed.size() || needed[mip]) && mine.levels[mip] != theirs.levels[mip]) return false;
    return true;
}

std::vector<BakeTiming> benchBakes(const BenchOptions& options, const std::vector<BenchEnvironment>& environments,
                                   const fs::path& cacheDir) {
    const fs::path scratch = fs::temp_directory_path() / fmt::format("iblkit-bake-bench.{}", getpid());
    fs::remove_all(scratch);
    fs::create_directories(scratch);
    const std::unique_ptr<const fs::path, void (*)(const fs::path*)> cleanup(&scratch, [](const fs::path* folder) {
        std::error_code ignored;
        fs::remove_all(*folder, ignored);
    });
    std::vector<std::pair<std::string, fs::path>> scenes;
    for (const auto& scene : benchScenes()) scenes.emplace_back(scene.name, writeBenchScene(scene, scratch));
    const auto worlds = blenderWorldsAmong(environments);
    BakeBench bench(options, scratch);
    const std::string sky = "sky";
    logBake(options, "warm-up");
    bench.run({BakeBench::kFull, sky, {}, {}, {}}); // Mesa's shader cache warm, as it is after any first run
    for (uint32_t repeat = 0; repeat < options.repeat; ++repeat) {
        logBake(options, fmt::format("repeat {} of {}", repeat + 1, options.repeat));
        const auto cache = scratch / fmt::format("cache-{}", repeat);
        {
            const MesaShaderCacheAt empty(scratch / fmt::format("mesa-{}", repeat));
            bench.run({"first, empty caches (the kit's and Mesa's)", sky, {}, {}, scratch / fmt::format("cold-{}", repeat)});
        }
        bench.run({BakeBench::kFull, sky, {}, {}, {}});
        bench.run({"first, empty cache", sky, {}, {}, cache});
        bench.run({"the same bake again", sky, {}, {}, cache});
        for (const auto& world : worlds) {
            const auto file = blenderWorlds(cacheDir) / (world + ".exr");
            bench.run({BakeBench::kFull, world, file, {}, {}});
            bench.run({"in a row, one cache", world, file, {}, cache});
        }
        for (const auto& [name, file] : scenes) bench.run({"scene: " + name + ", no cache", sky, {}, file, {}});
    }
    return bench.timings();
}

} // namespace iblkit::bench
