#include "size_curve.hpp"

#include "bake_settings.hpp"
#include "bench_environments.hpp"
#include "bench_error.hpp"
#include "scratch_folder.hpp"
#include "gpu_steps.hpp"
#include "measurements.hpp"
#include "timed_process.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <optional>
#include <set>

namespace iblkit::bench {
namespace {

namespace fs = std::filesystem;

uint32_t defaultSamplesOf(const std::string& method) {
    bake::BakeSettings settings;
    settings.specularMethod = method;
    return bake::resolveSettings(settings).sampleCount;
}

// The bake's own account of its largest resident set (--json's peak_mib): the kernel's for a
// child of this process would count this process's memory too (vfork).
double peakOf(const fs::path& summary, const std::string& what) {
    std::ifstream in(summary);
    const auto json = nlohmann::json::parse(in, nullptr, false);
    if (json.is_discarded() || !json.contains("peak_mib") || !json["peak_mib"].is_number())
        throw BenchError(fmt::format("could not {}: its summary has no peak memory", what));
    return json["peak_mib"].get<double>();
}

void logLine(const BenchOptions& options, const std::string& line) {
    if (!options.log) return;
    fmt::print(options.log, "bench  {}\n", line);
    std::fflush(options.log);
}

struct BakeCost {
    double wallMilliseconds = 0, peakMebibytes = 0;
};

class SizeCurve {
public:
    SizeCurve(const BenchOptions& options, const fs::path& scratch)
        : options_(options), scratch_(scratch), program_(fs::read_symlink("/proc/self/exe")) {}

    // The process's median wall time and peak memory over the repeats; the first bake of each
    // method is a warm-up (Mesa's shader cache, the page cache), as after any first run.
    BakeCost bakeCost(const std::string& environment, const fs::path& input, uint32_t size, const std::string& method) {
        std::vector<std::string> arguments{program_.string(), "bake"};
        if (!input.empty()) arguments.push_back(input.string());
        for (const auto& argument : {std::string("--size"), std::to_string(size), std::string("--method"), method,
                                     std::string("--no-cache"), std::string("--quiet"), std::string("--json"), std::string("-o"),
                                     (scratch_ / "bake").string()})
            arguments.push_back(argument);
        const auto what = fmt::format("bake {} at {}² with {}", environment, size, method);
        const auto summary = scratch_ / "bake.json", log = scratch_ / "bake.log";
        if (warm_.insert(method).second) runTimed(arguments, summary, log, what);
        std::vector<double> walls, peaks;
        for (uint32_t repeat = 0; repeat < options_.repeat; ++repeat) {
            walls.push_back(runTimed(arguments, summary, log, what));
            peaks.push_back(peakOf(summary, what));
        }
        return {median(walls), median(peaks)};
    }

private:
    const BenchOptions& options_;
    fs::path scratch_, program_;
    std::set<std::string> warm_;
};

} // namespace

std::vector<SizePoint> benchSizeCurve(const BenchOptions& options, const vulkan::VulkanContext& context,
                                      const ReferenceCache& cache, const fs::path& cacheDir) {
    const files::ScratchFolder scratch("size-curve");
    SizeCurve curve(options, scratch.path());
    std::vector<SizePoint> points;
    for (const auto& name : options.environments) {
        const auto input = bakeInputOf(name, cacheDir);
        if (!input) {
            logLine(options, fmt::format("size curve: '{}' has no file to bake, left out", name));
            continue;
        }
        for (const uint32_t size : options.sizes) {
            auto sized = options;
            sized.size = size;
            const auto environment = resolveEnvironments({name}, size, cacheDir).front();
            bake::BakeProgress quiet(true);
            auto source = bake::buildSourceCube(context, environment.input, size, quiet);
            const reference::MippedCube cube{size, source.desc().mips, source.download(context)};
            logLine(options, fmt::format("size curve: {} at {}², converged prefilter references", name, size));
            SpecularBench specular(context, source, cube, sized, cache);
            for (const std::string method : kSizeCurveMethods) {
                const uint32_t samples = defaultSamplesOf(method);
                const auto error = specular.measure(method, samples);
                const auto cost = curve.bakeCost(name, *input, size, method);
                points.push_back({name, method, size, samples, cost.wallMilliseconds, cost.peakMebibytes, options.repeat,
                                  error.errorRms, error.errorMax});
                logLine(options, fmt::format("size curve: {} {}² {}: {:.2f} s, {:.0f} MiB, RMS {:.3g} %, max {:.3g} %", name,
                                             size, method, cost.wallMilliseconds / 1e3, cost.peakMebibytes,
                                             100 * error.errorRms, 100 * error.errorMax));
            }
        }
    }
    return points;
}

} // namespace iblkit::bench
