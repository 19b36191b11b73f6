#include "sample_growth.hpp"

#include "error_stats.hpp"
#include "gl_bake.hpp"
#include "gpu_bake.hpp"
#include "kernels/sampled_methods.hpp"
#include "reference_bake.hpp"
#include "shader_paths.hpp"
#include "suite_inputs.hpp"

#include <algorithm>
#include <cmath>

namespace iblkit::stress {
namespace {

constexpr uint32_t kLutSize = 8, kPrefilterSize = 2, kEnvironmentSize = 16;
constexpr float kRoughness = 0.5f;
// llvmpipe ends a loop after 65535 iterations: the documents' whole-loop kernels stop there.
constexpr uint32_t kLoopLimit = 65535;
// Twice the largest error measured on lavapipe over every count, rounded up (docs/stability.md).
constexpr double kLutBound = 2e-5, kPrefilterBound = 6.4e-5;

// The suite's options (LUTs as R32G32_SFLOAT: the comparison measures sums, not storage) at `samples`.
compiler::CompileOptions withSamples(const consistency::SuiteRun& run, const char* kernel, uint32_t samples) {
    auto options = run.options.shaders.at(kernel);
    options.defines["SAMPLE_COUNT"] = std::to_string(samples);
    return options;
}

double maxError(const std::vector<float>& values, const std::vector<double>& reference, size_t& nonFinite) {
    const auto stats = consistency::measureError(values, reference);
    nonFinite += stats.nonFinite;
    return stats.maxAbsolute;
}

struct Estimator {
    const char* output;
    bool lut; // else the prefilter
    const char* documentKernel;
    const char* chunkKernel;
    double bound;
};

GrowthRow measure(const consistency::SuiteRun& run, const Estimator& estimator, uint32_t samples) {
    const auto& context = run.vulkan;
    const auto& gl = run.gl;
    using namespace consistency;
    const bool lut = estimator.lut;
    const reference::CubeEnvironment environment(kEnvironmentSize, testSuiteEnvironment().cube(kEnvironmentSize));
    const auto inDouble = lut ? reference::referenceBrdfLut<double>(kLutSize, samples)
                              : reference::referencePrefilter<double>(environment, double(kRoughness), kPrefilterSize, samples);
    const auto inFloat = lut ? reference::referenceBrdfLut<float>(kLutSize, samples)
                             : reference::referencePrefilter<float>(environment, kRoughness, kPrefilterSize, samples);
    GrowthRow row;
    row.output = estimator.output;
    row.samples = samples;
    row.bound = estimator.bound;
    row.singleLoopFloat = maxError(inFloat, inDouble, row.nonFinite);
    const uint32_t chunk = kernels::kChunkSamples;
    if (samples <= kLoopLimit) {
        const auto program = compileForPath(ShaderPath::Glslang, withSamples(run, estimator.documentKernel, samples));
        row.documentKernel = maxError(lut ? gpuBrdfLut(context, program, kLutSize)
                                          : gpuPrefilter(context, program, environment, kRoughness, kPrefilterSize),
                                      inDouble, row.nonFinite);
    }
    const auto chunkOptions = withSamples(run, estimator.chunkKernel, samples);
    const auto program = compileForPath(ShaderPath::Glslang, chunkOptions);
    const auto form = openGlForm(chunkOptions);
    row.chunkedVulkan = maxError(
        lut ? gpuBrdfLutChunks(context, program, kLutSize, samples, chunk)
            : gpuPrefilterChunks(context, program, environment, kRoughness, kPrefilterSize, samples, chunk),
        inDouble, row.nonFinite);
    row.chunkedOpenGl = maxError(
        lut ? glBrdfLutChunks(gl, form, kLutSize, samples, chunk)
            : glPrefilterChunks(gl, form, environment, kRoughness, kPrefilterSize, samples, chunk),
        inDouble, row.nonFinite);
    row.passed = row.nonFinite == 0 && std::max(row.chunkedVulkan, row.chunkedOpenGl) <= row.bound;
    return row;
}

} // namespace

std::vector<GrowthRow> sweepSampleCounts(const consistency::SuiteRun& run, bool reduced) {
    const Estimator estimators[] = {
        {"LUT 8² (IntegrateBRDF)", true, "PrecomputedBrdfCS", "PrecomputedBrdfChunkCS", kLutBound},
        {"prefilter 2², r = 0.5", false, "PrefilterSpecularCS", "PrefilterSpecularChunkCS", kPrefilterBound},
    };
    std::vector<uint32_t> counts;
    for (uint32_t exponent = 0; exponent <= 20; exponent += reduced ? 8 : 2) counts.push_back(1u << exponent);
    std::vector<GrowthRow> rows;
    for (const auto& estimator : estimators)
        for (const uint32_t samples : counts) rows.push_back(measure(run, estimator, samples));
    return rows;
}

} // namespace iblkit::stress
