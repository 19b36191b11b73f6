#include "bench_report.hpp"

#include "atomic_output.hpp"
#include "bench_error.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

namespace iblkit::bench {

const std::map<std::string, std::string>& embeddedBenchTools();

namespace {

namespace fs = std::filesystem;

// JSON has no infinity: a result that overflowed is written as null.
nlohmann::json number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

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
                           {"error_rms", number(result.errorRms)}, {"error_max", number(result.errorMax)},
                           {"mips", mips}});
    }
    return {{"machine", run.machine}, {"device", run.device}, {"date", run.date}, {"command", command},
            {"results", results}};
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

std::vector<std::string> drawPlots(const fs::path& resultsJson, const fs::path& folder) {
    const auto& script = embeddedBenchTools().at("tools/bench_plot.py");
    const auto listing = folder / ".plots.txt";
    // Debian's python3, which has python3-matplotlib; the script comes on stdin.
    const std::string command = fmt::format("/usr/bin/python3 - '{}' '{}' > '{}'", resultsJson.string(), folder.string(),
                                            listing.string());
    std::FILE* python = popen(command.c_str(), "w");
    if (!python) throw BenchError("could not start /usr/bin/python3 to draw the plots");
    std::fwrite(script.data(), 1, script.size(), python);
    const int status = pclose(python);
    std::ifstream in(listing);
    std::vector<std::string> plots;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) plots.push_back(line);
    fs::remove(listing);
    if (status != 0)
        throw BenchError("tools/bench_plot.py could not draw the plots (it needs Debian's python3-matplotlib)");
    return plots;
}

} // namespace

std::vector<std::string> writeBenchResults(const BenchRun& run, const std::string& command, const fs::path& folder) {
    fs::create_directories(folder);
    files::writeFileAtomically(folder / "results.json", resultsJson(run, command).dump(2) + "\n");
    files::writeFileAtomically(folder / "results.csv", resultsCsv(run));
    return drawPlots(folder / "results.json", folder);
}

} // namespace iblkit::bench
