#include "bench_curves.hpp"

#include "bake_error.hpp"

#include <algorithm>
#include <sstream>

namespace iblkit::bake {

const std::map<std::string, std::string>& embeddedBenchResults(); // generated: docs/bench/results.csv

namespace {

std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    return fields;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

} // namespace

const BenchCurves& BenchCurves::builtIn() {
    static const BenchCurves curves(embeddedBenchResults().at("docs/bench/results.csv"));
    return curves;
}

// Columns: output,environment,method,samples,chunk_samples,mip,roughness,texels,repeat,device_ms,wall_ms,error_rms,error_max
BenchCurves::BenchCurves(const std::string& csv) {
    std::stringstream stream(csv);
    std::string line;
    std::getline(stream, line); // the header
    while (std::getline(stream, line)) {
        const auto fields = splitCsvLine(line);
        if (fields.size() != 13) throw BakeError("internal error: the built-in bench results have a malformed line: " + line);
        BenchRow row;
        row.output = fields[0];
        row.environment = fields[1];
        row.method = fields[2];
        row.samples = uint32_t(std::stoul(fields[3]));
        if (!fields[5].empty()) row.mip = uint32_t(std::stoul(fields[5]));
        row.deviceMs = std::stod(fields[9]);
        row.errorRms = std::stod(fields[11]);
        row.errorMax = std::stod(fields[12]);
        rows_.push_back(std::move(row));
    }
}

std::optional<MeasuredCurve> BenchCurves::curve(const std::string& output, const std::string& method, uint32_t samples) const {
    MeasuredCurve curve;
    std::vector<double> times;
    for (const auto& row : rows_) {
        if (row.output != output || row.method != method || row.samples != samples) continue;
        if (row.mip) {
            auto& [rms, max] = curve.worstMipError[*row.mip];
            rms = std::max(rms, row.errorRms);
            max = std::max(max, row.errorMax);
            continue;
        }
        times.push_back(row.deviceMs);
        curve.worstErrorRms = std::max(curve.worstErrorRms, row.errorRms);
        curve.worstErrorMax = std::max(curve.worstErrorMax, row.errorMax);
    }
    if (times.empty()) return std::nullopt;
    curve.medianDeviceMs = median(times);
    curve.environments = times.size();
    return curve;
}

} // namespace iblkit::bake
