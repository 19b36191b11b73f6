// The LUT and prefilter kernels: the documents' shaders and their chunked twins.
#include "gpu_bake.hpp"
#include "reference_bake.hpp"
#include "suite_run.hpp"

#include <fmt/core.h>

namespace iblkit::consistency {

void addSampledLutOutputs(SuiteRun& run) {
    const auto& options = run.options;
    for (const uint32_t size : options.lutSizes) {
        addOutput(run, {"PrecomputedBrdfCS", fmt::format("LUT {}²", size), lutBounds(size)},
                  [&] { return References{reference::referenceBrdfLut<float>(size, options.sampleCount),
                   reference::referenceBrdfLut<double>(size, options.sampleCount)}; },
                  [&](const PathProgram& program) { return gpuBrdfLut(run.vulkan, program, size); },
                  [&](const OpenGlForm& form) { return glBrdfLut(run.gl, form, size); });
    }
}

void addSampledPrefilterOutputs(SuiteRun& run) {
    const auto& options = run.options;
    const reference::CubeEnvironment environment(options.environmentSize, options.environment.cube(options.environmentSize));
    const uint32_t size = options.prefilterSize;
    for (const float roughness : options.roughnesses) {
        addOutput(run, {"PrefilterSpecularCS", fmt::format("prefilter {}² r={}", size, roughness), prefilterBounds()},
                  [&] { return References{reference::referencePrefilter<float>(environment, roughness, size, options.sampleCount),
                   reference::referencePrefilter<double>(environment, double(roughness), size, options.sampleCount)}; },
                  [&](const PathProgram& program) { return gpuPrefilter(run.vulkan, program, environment, roughness, size); },
                  [&](const OpenGlForm& form) { return glPrefilter(run.gl, form, environment, roughness, size); });
    }
}

// The same references as the whole-loop shaders: the chunks only regroup the float sums.
void addChunkedLutOutput(SuiteRun& run) {
    const auto& options = run.options;
    const uint32_t samples = options.sampleCount, chunk = options.chunkSamples;
    const uint32_t lutSize = options.chunkLutSize;
    addOutput(run, {"PrecomputedBrdfChunkCS", fmt::format("LUT {}² in chunks of {}", lutSize, chunk), lutChunkBounds()},
              [&] { return References{reference::referenceBrdfLut<float>(lutSize, samples), reference::referenceBrdfLut<double>(lutSize, samples)}; },
              [&](const PathProgram& program) { return gpuBrdfLutChunks(run.vulkan, program, lutSize, samples, chunk); },
              [&](const OpenGlForm& form) { return glBrdfLutChunks(run.gl, form, lutSize, samples, chunk); });
}

void addChunkedPrefilterOutput(SuiteRun& run) {
    const auto& options = run.options;
    const uint32_t samples = options.sampleCount, chunk = options.chunkSamples;
    const reference::CubeEnvironment environment(options.environmentSize, options.environment.cube(options.environmentSize));
    const uint32_t size = options.prefilterSize;
    const float roughness = options.chunkRoughness;
    addOutput(run, {"PrefilterSpecularChunkCS", fmt::format("prefilter {}² r={} in chunks of {}", size, roughness, chunk),
                    prefilterChunkBounds()},
              [&] { return References{reference::referencePrefilter<float>(environment, roughness, size, samples),
               reference::referencePrefilter<double>(environment, double(roughness), size, samples)}; },
              [&](const PathProgram& program) {
                  return gpuPrefilterChunks(run.vulkan, program, environment, roughness, size, samples, chunk);
              },
              [&](const OpenGlForm& form) {
                  return glPrefilterChunks(run.gl, form, environment, roughness, size, samples, chunk);
              });
}

} // namespace iblkit::consistency
