#include "bench_report.hpp"

#include "atomic_output.hpp"
#include "bake_directory.hpp"
#include "bake_error.hpp"
#include "bake_manifest.hpp"
#include "bake_outputs.hpp"
#include "bench_error.hpp"
#include "scratch_folder.hpp"
#include "files.hpp"
#include "embedded_tools.hpp"
#include "shell_command.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <span>
#include <unistd.h>

namespace iblkit::bench {
namespace {

namespace fs = std::filesystem;

// JSON has no infinity: a result that overflowed is written as null.
nlohmann::json number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

nlohmann::json sizeCurveJson(const std::vector<SizePoint>& points) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& point : points)
        rows.push_back({{"environment", point.environment}, {"method", point.method}, {"size", point.size},
                        {"samples", point.samples}, {"wall_ms", point.wallMilliseconds}, {"peak_mib", point.peakMebibytes},
                        {"repeat", point.repeat}, {"error_rms", number(point.errorRms)}, {"error_max", number(point.errorMax)}});
    return rows;
}

nlohmann::json resultsJson(const BenchRun& run, const std::string& command) {
    nlohmann::json results = nlohmann::json::array();
    for (const auto& result : run.results) {
        nlohmann::json mips = nlohmann::json::array();
        for (const auto& mip : result.mips)
            mips.push_back({{"mip", mip.mip}, {"roughness", mip.roughness}, {"texels", mip.texels},
                            {"rms", number(mip.rms)}, {"max", number(mip.max)}});
        results.push_back({{"output", outputName(result.output)}, {"environment", result.environment},
                           {"method", result.method}, {"samples", result.samples},
                           {"chunk_samples", result.chunkSamples}, {"device_ms", result.deviceMilliseconds},
                           {"wall_ms", result.wallMilliseconds}, {"repeat", result.repeat},
                           {"error_rms", number(result.errorRms)}, {"error_max", number(result.errorMax)}, {"half_steps", result.halfSteps},
                           {"seam_jump", number(result.seamJump)}, {"reference_seam_jump", number(result.referenceSeamJump)},
                           {"mips", mips}});
    }
    nlohmann::json bakes = nlohmann::json::array();
    for (const auto& bake : run.bakes)
        bakes.push_back({{"bake", bake.bake}, {"environment", bake.environment}, {"computed", bake.computed},
                         {"wall_ms", bake.wallMilliseconds}, {"full_wall_ms", bake.fullWallMilliseconds},
                         {"repeat", bake.repeat}, {"identical", bake.identical}});
    nlohmann::json batches = nlohmann::json::array();
    for (const auto& batch : run.batches)
        batches.push_back({{"cache", batch.cache}, {"bakes", batch.bakes}, {"separate_ms", batch.separateMilliseconds},
                           {"batch_ms", batch.batchMilliseconds}, {"ratio", batch.ratio}, {"ratio_min", batch.ratioMin},
                           {"ratio_max", batch.ratioMax}, {"environment_ms", batch.environmentMilliseconds},
                           {"repeat", batch.repeat}});
    return {{"machine", run.machine}, {"device", run.device}, {"date", run.date}, {"command", command},
            {"results", results}, {"bakes", bakes}, {"size_curve", sizeCurveJson(run.sizeCurve)}, {"batches", batches}};
}

std::string csvRow(const BenchResult& result, const std::string& mip, double roughness, uint32_t texels, double rms,
                   double max) {
    return fmt::format("{},{},{},{},{},{},{},{},{},{:.4f},{:.4f},{:.6e},{:.6e}\n", outputName(result.output),
                       result.environment, result.method, result.samples, result.chunkSamples, mip,
                       roughness < 0 ? std::string() : fmt::format("{}", roughness), texels, result.repeat,
                       result.deviceMilliseconds, result.wallMilliseconds, rms, max);
}

// One row per result (mip empty: the result's own errors), then one per specular mip.
std::string resultsCsv(const BenchRun& run) {
    std::string text = "output,environment,method,samples,chunk_samples,mip,roughness,texels,repeat,device_ms,wall_ms,"
                       "error_rms,error_max\n";
    for (const auto& result : run.results) {
        text += csvRow(result, "", -1, 0, result.errorRms, result.errorMax);
        for (const auto& mip : result.mips)
            text += csvRow(result, std::to_string(mip.mip), mip.roughness, mip.texels, mip.rms, mip.max);
    }
    return text;
}

std::string readWhole(const fs::path& path) {
    const auto bytes = image_io::readFileBytes(path);
    return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

// Debian's python3, which has python3-matplotlib; the script comes on stdin.
constexpr const char* kPython = "/usr/bin/python3";

// The plots of results.json as drawn into `scratch`: (file name, PNG bytes).
std::vector<std::pair<std::string, std::string>> drawPlots(const fs::path& resultsJson, const fs::path& scratch) {
    const auto listing = scratch / "plots.txt";
    const auto plots = scratch / "plots";
    const std::string command = fmt::format("{} - {} {} > {}", kPython, shellQuoted(resultsJson), shellQuoted(plots),
                                            shellQuoted(listing));
    if (runWithInput(command, embeddedBenchTools().at("tools/bench_plot.py")) != 0)
        throw BenchError("tools/bench_plot.py could not draw the plots (see its message above)");
    std::ifstream in(listing);
    std::vector<std::pair<std::string, std::string>> drawn;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) drawn.emplace_back(line, readWhole(plots / line));
    return drawn;
}

} // namespace

void checkResultsWritable(const fs::path& folder, const fs::path& markdownFile, const std::vector<std::string>& environments) {
    if (std::system(fmt::format("{} -c 'import matplotlib' 2>/dev/null", kPython).c_str()) != 0)
        throw BenchError(fmt::format("the plots need {} with matplotlib (Debian's python3-matplotlib)", kPython));
    if (fs::exists(folder) && !fs::is_directory(folder))
        throw BenchError("--out " + folder.string() + " is not a folder");
    std::vector<fs::path> inputs;
    for (const auto& environment : environments)
        if (std::error_code error; fs::is_regular_file(environment, error)) inputs.emplace_back(environment);
    std::vector<fs::path> outputs{folder / "results.json", folder / "results.csv"};
    if (!markdownFile.empty()) outputs.push_back(markdownFile);
    try {
        if (!markdownFile.empty()) files::requireWritableFile(markdownFile, "--markdown");
        files::requireDistinctOutputs(outputs, inputs);
        bake::checkBakeTarget(folder, std::nullopt, "bench");
    } catch (const files::FileError& error) {
        throw BenchError(error.what());
    } catch (const bake::BakeError& error) {
        throw BenchError("--out " + std::string(error.what()));
    }
}

std::vector<std::string> writeBenchResults(const BenchRun& run, const std::string& command, const fs::path& folder,
                                           const fs::path& markdownFile) {
    const files::ScratchFolder scratch("bench");
    const auto json = resultsJson(run, command).dump(2) + "\n";
    files::writeFileAtomically(scratch.path() / "results.json", json);
    // Whole bakes alone have nothing to plot but their cost curve.
    const auto plots = run.results.empty() && run.sizeCurve.empty() ? std::vector<std::pair<std::string, std::string>>{}
                                           : drawPlots(scratch.path() / "results.json", scratch.path());
    // The folder is the bench's own, replaced as a whole, its manifest listing what it holds (as a
    // bake's does); the Markdown file is written beside it, all or nothing.
    bake::BakeDirectory directory(folder, std::nullopt, "bench");
    const auto& staging = directory.staging();
    const auto bytesOf = [](const std::string& text) { return std::as_bytes(std::span(text.data(), text.size())); };
    std::vector<bake::WrittenFile> written{bake::writeBytes(staging, "results.json", bytesOf(json)),
                                           bake::writeBytes(staging, "results.csv", bytesOf(resultsCsv(run)))};
    std::vector<std::string> names;
    for (const auto& [name, bytes] : plots) {
        written.push_back(bake::writeBytes(staging, name, bytesOf(bytes)));
        names.push_back(name);
    }
    const nlohmann::json manifest = {{"generator", "iblkit"}, {"command", "bench"}, {"invocation", command},
                                     {"files", bake::filesJson(written)}};
    bake::writeBytes(staging, "manifest.json", bytesOf(manifest.dump(2) + "\n"));
    files::AtomicOutput markdown;
    if (!markdownFile.empty()) markdown.add(markdownFile, renderBenchMarkdown(run, command, folder, names, markdownFile));
    directory.commit();
    markdown.commit();
    return names;
}

} // namespace iblkit::bench
