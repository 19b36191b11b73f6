#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::bake {

// One row of the bench's results (docs/bench/results.csv): an output ("specular", "lut",
// "irradiance") made by a method at a sample count on one environment, its device time and its
// error against the converged reference, for the whole output (mip empty) or one specular mip.
struct BenchRow {
    std::string output, environment, method;
    uint32_t samples = 0;
    std::optional<uint32_t> mip;
    double deviceMs = 0, errorRms = 0, errorMax = 0;
};

// What the bench measured for one output, method and count across its environments: the median
// device time of the whole output, and the worst error of the whole output and of each mip.
struct MeasuredCurve {
    double medianDeviceMs = 0;
    double worstErrorRms = 0, worstErrorMax = 0;
    std::map<uint32_t, std::pair<double, double>> worstMipError; // mip -> (rms, max)
    size_t environments = 0;
};

// The bench's results as the program was built (docs/bench/results.csv, built into it), with the
// cube, LUT and irradiance sizes they were measured at.
class BenchCurves {
public:
    static const BenchCurves& builtIn();
    explicit BenchCurves(const std::string& csv);

    std::optional<MeasuredCurve> curve(const std::string& output, const std::string& method, uint32_t samples) const;
    uint32_t cubeSize() const { return cubeSize_; }
    uint32_t lutSize() const { return lutSize_; }
    uint32_t irradianceSize() const { return irradianceSize_; }

private:
    std::vector<BenchRow> rows_;
    uint32_t cubeSize_ = 256, lutSize_ = 512, irradianceSize_ = 32;
};

} // namespace iblkit::bake
