#include "bake_command.hpp"

#include "bake_options.hpp"
#include "run_command.hpp"
#include "signal_cleanup.hpp"

#include <iblkit/bake.hpp>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <ctime>
#include <fstream>
#include <memory>
#include <sstream>

#include <unistd.h>

namespace iblkit::cli {
namespace {

// How long this process has run, from the kernel's record of its start (in steps of 10 ms; 0
// where there is no /proc).
double processAgeMilliseconds() {
    std::ifstream stat("/proc/self/stat");
    std::string line;
    if (!std::getline(stat, line)) return 0;
    // Field 22, the start in clock ticks since boot, counted after the command's name, which ends
    // at the last ')' and may hold spaces.
    std::istringstream fields(line.substr(line.rfind(')') + 2));
    std::string field;
    for (int index = 3; index < 22 && fields >> field; ++index) {}
    unsigned long long startTicks = 0;
    if (!(fields >> startTicks)) return 0;
    timespec now{};
    clock_gettime(CLOCK_BOOTTIME, &now);
    const double started = double(startTicks) / double(sysconf(_SC_CLK_TCK));
    return std::max(0.0, (double(now.tv_sec) + double(now.tv_nsec) * 1e-9 - started) * 1e3);
}

// The bake's summary with the process's own times: "start", from the program's start to the
// bake's, as the first step, and "process_ms", from the program's start to now. What the
// process does after it prints (freeing its memory, exiting) is in no summary.
std::string withProcessTimes(const std::string& summaryJson, double startMilliseconds) {
    auto summary = nlohmann::json::parse(summaryJson);
    const nlohmann::json start{{"name", "start"}, {"device_ms", 0}, {"wall_ms", startMilliseconds}};
    summary["steps"].insert(summary["steps"].begin(), start);
    summary["process_ms"] = processAgeMilliseconds();
    return summary.dump(2);
}

void printSummary(const BakeSummary& summary) {
    fmt::print(stderr, "baked {} on {} in {:.2f} s:", summary.folder.string(), summary.device,
               summary.wallMilliseconds / 1e3);
    for (const auto& file : summary.files)
        if (file.name.find('/') == std::string::npos) fmt::print(stderr, " {}", file.name);
    fmt::print(stderr, "\n");
}

} // namespace

void printPolicyReports(const BakeSummary& summary, const std::string& prefix) {
    for (const auto& clamp : summary.halfRangeClamps)
        fmt::print(stderr, "{}warning: clamped {} values of {} past the 16-bit float range to 65504: mip {} lost {:.3g} % "
                           "of its energy (--strict refuses them)\n",
                   prefix, clamp.values, clamp.texture, clamp.worstMip, 100 * clamp.worstShare);
    if (summary.negativeTexels)
        fmt::print(stderr, "{}clamped {} input texels of negative radiance to 0, down to {:g} (--strict refuses them)\n", prefix,
                   summary.negativeTexels, summary.mostNegative);
    for (const auto& warning : summary.cacheWarnings) fmt::print(stderr, "{}warning: {}\n", prefix, warning);
    for (const auto& note : summary.sceneNotes) fmt::print(stderr, "{}warning: {}\n", prefix, note);
    const auto sanitized = summary.sanitizedTexels;
    if (sanitized) fmt::print(stderr, "{}replaced {} NaN/Inf input texels by 0 (--sanitize)\n", prefix, sanitized);
}

void addBakeCommand(CLI::App& app) {
    struct Arguments {
        BakeLineArguments line;
        std::filesystem::path outputDir;
        std::string cache;
        bool noCache = false;
        bool quiet = false;
        bool json = false;
    };
    auto arguments = std::make_shared<Arguments>();
    auto& s = arguments->line.request;
    auto* command = app.add_subcommand(
        "bake", "Bake an HDR environment into a prefiltered specular cube, a BRDF LUT, irradiance and a preview");
    addBakeLineOptions(*command, arguments->line);
    command->add_option("-o,--output", arguments->outputDir, "Output folder (replaced as a whole when the bake succeeds)")
        ->required();
    command->add_option("--cache", arguments->cache,
                        "Cache folder: each output is kept under the hash of everything it depends on, and taken "
                        "from there when nothing it depends on changed (default $XDG_CACHE_HOME/iblkit, else ~/.cache/iblkit)");
    command->add_flag("--no-cache", arguments->noCache, "Compute everything, and keep nothing");
    command->add_flag("--validate", s.validation, "Run with the Vulkan validation layer; any message fails the bake");
    command->add_option("--device", s.device, "Device index or part of its name (default: lavapipe)");
    command->add_flag("-q,--quiet", arguments->quiet,
                      "No progress on stderr (what the input policies clamped is still reported)");
    command->add_flag("--json", arguments->json, "Print a summary with per-step device and wall times as JSON");
    command->callback([arguments] {
        files::cleanUpOnSignals(); // first: the Vulkan driver's threads must inherit the blocked signals
        const double startMilliseconds = processAgeMilliseconds();
        auto request = arguments->line.resolved();
        if (arguments->noCache && !arguments->cache.empty()) throw CLI::ValidationError("--cache and --no-cache", "give one of them");
        if (!arguments->noCache)
            request.cache = arguments->cache.empty() ? defaultCacheFolder() : std::filesystem::path(arguments->cache);
        request.quiet = arguments->quiet;
        const auto summary = bakeToFolder(request, arguments->outputDir);
        for (const auto& message : summary.validationMessages) fmt::print(stderr, "validation: {}\n", message);
        if (!summary.validationMessages.empty()) throw ExpectationsFailed{};
        if (arguments->json) fmt::print("{}\n", withProcessTimes(summary.json, startMilliseconds));
        if (!arguments->quiet) printSummary(summary);
        printPolicyReports(summary);
    });
}

} // namespace iblkit::cli
