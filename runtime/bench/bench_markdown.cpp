#include "bench_report.hpp"

#include "bench_frontier.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace iblkit::bench {
namespace {

namespace fs = std::filesystem;

// The error targets the kit's defaults must meet on every environment.
constexpr double kTargetRms = 0.01, kTargetMax = 0.05;

std::string percent(double value) {
    if (!std::isfinite(value)) return "inf";
    return value >= 0.1 ? fmt::format("{:.1f} %", 100 * value) : fmt::format("{:.2g} %", 100 * value);
}

std::string seconds(double milliseconds) { return fmt::format("{:.3g}", milliseconds / 1e3); }

std::vector<std::string> environmentsOf(const BenchRun& run) {
    std::vector<std::string> names;
    for (const auto& result : run.results)
        if (result.output == BenchOutput::Specular &&
            std::find(names.begin(), names.end(), result.environment) == names.end())
            names.push_back(result.environment);
    return names;
}

std::string specularTable(const std::vector<const BenchResult*>& results) {
    if (results.empty()) return {};
    const auto& mips = results.front()->mips;
    std::string header = "| method | samples | device s | wall s | seam jump (converged) |", rule = "|---|---:|---:|---:|---:|";
    for (const auto& mip : mips) {
        header += fmt::format(" mip {} (r {:.2f}) RMS / max |", mip.mip, mip.roughness);
        rule += "---:|";
    }
    std::string text = header + "\n" + rule + "\n";
    for (const auto* result : results) {
        text += fmt::format("| {} | {} | {} | {} | {} ({}) |", result->method, result->samples,
                            seconds(result->deviceMilliseconds), seconds(result->wallMilliseconds),
                            percent(result->seamJump), percent(result->referenceSeamJump));
        for (const auto& mip : result->mips) text += fmt::format(" {} / {} |", percent(mip.rms), percent(mip.max));
        text += "\n";
    }
    return text;
}

// The fastest configuration of each method that meets both targets on the environment.
std::string targetTable(const BenchRun& run, const std::vector<std::string>& environments) {
    std::set<std::string> methods;
    for (const auto& result : run.results)
        if (result.output == BenchOutput::Specular) methods.insert(result.method);
    std::string text = fmt::format("| environment | method | fastest within {} RMS and {} max | device s | best RMS / max "
                                   "reached |\n|---|---|---|---:|---|\n",
                                   percent(kTargetRms), percent(kTargetMax));
    for (const auto& environment : environments)
        for (const auto& method : methods) {
            const BenchResult *fastest = nullptr, *best = nullptr;
            for (const auto* result : resultsOf(run, BenchOutput::Specular, environment)) {
                if (result->method != method) continue;
                if (!best || result->errorRms < best->errorRms) best = result;
                const bool meets = result->errorRms <= kTargetRms && result->errorMax <= kTargetMax;
                if (meets && (!fastest || result->deviceMilliseconds < fastest->deviceMilliseconds)) fastest = result;
            }
            if (!best) continue;
            text += fmt::format("| {} | {} | {} | {} | {} / {} at {} samples |\n", environment, method,
                                fastest ? fmt::format("{} samples", fastest->samples) : "not reached",
                                fastest ? seconds(fastest->deviceMilliseconds) : "—", percent(best->errorRms),
                                percent(best->errorMax), best->samples);
        }
    return text;
}

std::string lutTable(const BenchRun& run) {
    std::string text = "| method | samples (nodes per panel) | device s | wall s | max abs error | RMS abs error | RG16F: "
                       "furthest texel, half steps |\n|---|---:|---:|---:|---:|---:|---:|\n";
    for (const auto* result : resultsOf(run, BenchOutput::Lut, {}))
        text += fmt::format("| {} | {} | {} | {} | {:.2e} | {:.2e} | {} |\n", result->method, result->samples,
                            seconds(result->deviceMilliseconds), seconds(result->wallMilliseconds), result->errorMax,
                            result->errorRms, result->halfSteps);
    return text;
}

std::string irradianceTable(const BenchRun& run) {
    std::string text = "| environment | method | device s | wall s | RMS | max |\n|---|---|---:|---:|---:|---:|\n";
    for (const auto* result : resultsOf(run, BenchOutput::Irradiance, {}))
        text += fmt::format("| {} | {} | {} | {} | {} | {} |\n", result->environment, result->method,
                            seconds(result->deviceMilliseconds), seconds(result->wallMilliseconds),
                            percent(result->errorRms), percent(result->errorMax));
    return text;
}

std::string bakeTable(const std::vector<BakeTiming>& bakes) {
    std::string text = "| bake | environment | computed on the device | wall s | full bake s | speed-up | needed values |\n"
                       "|---|---|---|---:|---:|---:|---|\n";
    double row = 0, rowFull = 0;
    for (const auto& bake : bakes) {
        text += fmt::format("| {} | {} | {} | {} | {} | {:.2g}× | {} |\n", bake.bake, bake.environment, bake.computed,
                            seconds(bake.wallMilliseconds), seconds(bake.fullWallMilliseconds),
                            bake.fullWallMilliseconds / bake.wallMilliseconds, bake.identical ? "the full bake's" : "**differ**");
        if (bake.bake.starts_with("in a row")) {
            row += bake.wallMilliseconds;
            rowFull += bake.fullWallMilliseconds;
        }
    }
    if (row > 0)
        text += fmt::format("\nThe environments in a row: {} s on one cache against {} s baked in full ({:.2g}×).\n",
                            seconds(row), seconds(rowFull), rowFull / row);
    return text;
}

std::string batchTable(const std::vector<BatchTiming>& batches) {
    std::string text = "| caches | bakes | separate processes s | one batch s | batch / separate | min – max | the batch's "
                       "environment work s | the batch over that work |\n|---|---:|---:|---:|---:|---|---:|---:|\n";
    for (const auto& batch : batches)
        text += fmt::format("| {} | {} | {} | {} | {:.3f} | {:.3f} – {:.3f} | {} | +{:.1f} % |\n", batch.cache, batch.bakes,
                            seconds(batch.separateMilliseconds), seconds(batch.batchMilliseconds), batch.ratio, batch.ratioMin,
                            batch.ratioMax, seconds(batch.environmentMilliseconds),
                            100 * (batch.batchMilliseconds / batch.environmentMilliseconds - 1));
    return text;
}

std::string sizeCurveTable(const std::vector<SizePoint>& points) {
    std::string text = "| environment | method | count | size | wall s | peak MiB | specular RMS / max |\n"
                       "|---|---|---:|---:|---:|---:|---|\n";
    for (const auto& point : points)
        text += fmt::format("| {} | {} | {} | {}² | {} | {:.0f} | {} / {} |\n", point.environment, point.method, point.samples,
                            point.size, seconds(point.wallMilliseconds), point.peakMebibytes, percent(point.errorRms),
                            percent(point.errorMax));
    return text;
}

std::string images(const std::vector<std::string>& plots, const std::string& prefix, const fs::path& relativeFolder) {
    std::string text;
    for (const auto& plot : plots)
        if (plot.starts_with(prefix)) text += fmt::format("![{}]({})\n\n", plot, (relativeFolder / plot).generic_string());
    return text;
}

} // namespace

std::string renderBenchMarkdown(const BenchRun& run, const std::string& command, const fs::path& folder,
                                const std::vector<std::string>& plots, const fs::path& markdownFile) {
    const auto base = markdownFile.parent_path().empty() ? fs::path(".") : markdownFile.parent_path();
    const auto relativeFolder = fs::relative(folder, base);
    const auto environments = environmentsOf(run);
    std::string text = "# Benchmark: time against error\n\n";
    text += fmt::format("Made by `{}` on {}; do not edit. The numbers are in [results.csv]({}) and [results.json]({}).\n\n",
                        command, run.date, (relativeFolder / "results.csv").generic_string(),
                        (relativeFolder / "results.json").generic_string());
    text += fmt::format("- Machine: {}\n- Device: {}\n", run.machine, run.device);
    text += "- Times: device time from Vulkan timestamps summed over a configuration's dispatches, and wall time from "
            "the first dispatch to the last one's completion, each the median of the repeats; shader compilation is "
            "not included.\n"
            "- Specular: the prefiltered mips 1 and up, as the bake makes them, against the converged prefilter integral "
            "(the exact sum over the source cube's texels with their solid angles) at seeded texels of each mip; the "
            "error is the relative error of luminance, RMS and max per mip. A configuration's error is its worst mip's. "
            "The estimators read the source through bilinear filtering where the reference takes each texel as "
            "constant: a floor of about 8e-4 relative on a smooth 64² cube (tests/reference), far below the 1 % target. "
            "A count is samples per texel, except for the table (mip 1's samples, doubling per mip), the pyramid (reads "
            "per texel along the normal, at most 4, where the lobe is narrow; 9 reads, one along the normal and 8 "
            "around it, where it is wide), the mip chain (no count: a copy of the source's mip where the lobe is "
            "narrow, the pyramid's ring where it is wide) and the convolution (its budget of terms per texel).\n"
            "- Seams: the largest relative jump of luminance between texels facing each other across a face edge "
            "(4 pairs per edge and mip, over the mips), beside the same jump of the converged integral at the same "
            "texels: a jump well above the converged one is a visible seam.\n"
            "- LUT: every texel of the grid, scale and bias, against the converged quadrature; absolute error. A count is "
            "samples per texel, except for the quadrature (Gauss-Legendre nodes per panel), the quadrature grid (nodes "
            "per side) and the fit (the polynomial's degree). The RG16F column rounds both to half "
            "floats: 0 or 1 steps apart is the target (the converged value's nearest half, or its neighbour).\n"
            "- Irradiance: every texel against the exact sum over the source cube; relative error of luminance.\n\n";
    if (!environments.empty()) {
        text += "## Specular\n\n" + images(plots, "specular_summary", relativeFolder);
        text += "### Time to reach the targets\n\n" + targetTable(run, environments) + "\n";
        text += "### Lowest error at each time budget\n\nSpecular by the worst mip's RMS, the LUT by its max error; a "
                "budget below a row's first time reaches nothing.\n\n" +
                frontierTable(run, environments) + "\n";
    }
    for (const auto& environment : environments) {
        text += fmt::format("### {}\n\n", environment);
        text += images(plots, "specular_" + environment + ".", relativeFolder);
        text += specularTable(resultsOf(run, BenchOutput::Specular, environment)) + "\n";
    }
    if (!resultsOf(run, BenchOutput::Lut, {}).empty())
        text += "## BRDF LUT\n\n" + images(plots, "lut", relativeFolder) + lutTable(run) + "\n";
    if (!resultsOf(run, BenchOutput::Irradiance, {}).empty())
        text += "## Irradiance\n\n" + images(plots, "irradiance", relativeFolder) + irradianceTable(run);
    if (!run.bakes.empty())
        text += "\n## Whole bakes: what the cache and the plan skip\n\n"
                "`iblkit bake` with its default settings, run in the bench's process: each time is the bake's own wall "
                "time, from loading the environment to the last file written (the program's start is not in it), the "
                "median of the repeats. \"Empty caches\" is a fresh machine's first bake: the kit's cache and Mesa's "
                "shader cache (where lavapipe keeps the code LLVM compiled) both empty; every other bake finds Mesa's "
                "warm. \"In a row\" bakes the Blender worlds one after the other on the cache the sky's bakes filled: "
                "the LUT and the compiled kernels come from it. The scenes (bench_scenes.cpp) are baked without a "
                "cache. \"Needed values\" compares the files with the same environment's full bake wherever the plan "
                "needs values (every output it writes; of the specular chain, the prefiltered mips): bit for bit the "
                "same is the full bake's error, unchanged.\n\n" +
                bakeTable(run.bakes);
    if (!run.batches.empty())
        text += "\n## Batches: many bakes in one process\n\n"
                "The environments as one `iblkit batch` list with the bake's default settings, against one `iblkit bake` "
                "process each, as whole processes: the separate bakes' walls summed, then the batch's, in pairs whose "
                "order alternates, each time the median over the pairs after a warm-up pair. \"Fresh cache\": each side "
                "of each pair starts on an empty cache of its own, as default bakes on a new machine (the separate "
                "bakes share theirs: the first one's LUT serves the rest); \"no cache\": `--no-cache` on both. Every "
                "folder the batch writes is byte for byte the separate bake's. The environment work is what no batch "
                "can share: the batch's bakes' source cube, lights, irradiance, prefilter and preview steps, summed; "
                "the last column is what the batch spends beyond it.\n\n" +
                batchTable(run.batches);
    if (!run.sizeCurve.empty())
        text += "\n## Cost against size\n\n" + images(plots, "size_curve", relativeFolder) +
                "`iblkit bake ENV --size N --no-cache --method M` as a whole process, the default method (the convolution "
                "at its default budget) and the documents' (importance sampling at their default count): wall time "
                "from the program's start to its exit and peak memory (the largest resident set), each the median of "
                "the repeats after a warm-up per method. The error is the method's at that count on the same size's "
                "source cube, measured as in the specular tables: the worst mip's luminance error at the bench's "
                "seeded texels against the converged references.\n\n" +
                sizeCurveTable(run.sizeCurve);
    return text;
}

} // namespace iblkit::bench
