// The prefilter methods that read the source's mips: filtered importance sampling, its host
// sample table, and the pyramid's reads along the normal and around its ring, over the test
// environment with its whole chain.
#include "filtered_prefilter.hpp"
#include "gl_cube_bake.hpp"
#include "gpu_cube_bake.hpp"
#include "kernels/pyramid_method.hpp"
#include "prefilter_sample_table.hpp"
#include "suite_run.hpp"

#include <bit>

#include <fmt/core.h>

namespace iblkit::consistency {
namespace {

constexpr uint32_t kSuitePyramidReads = 2; // READ_COUNT in hlsl/shaders.json
constexpr uint32_t kSuiteRingReads = 8;    // RING_COUNT in hlsl/shaders.json

void addRingOutput(SuiteRun& run, const MippedCube& cube, const reference::MippedEnvironment& source,
                   const reference::PyramidRing& ring, float roughness) {
    const uint32_t size = run.options.prefilterSize;
    const auto parameters = kernels::ringParameters(ring);
    addOutput(run, {"PrefilterRingCS", fmt::format("prefilter {}² r={}, a read along N and {} around it", size, roughness,
                                                   kSuiteRingReads),
                    ringBounds()},
              [&] { return References{reference::referenceRingPrefilter<float>(source, ring, kSuiteRingReads, size),
               reference::referenceRingPrefilter<double>(source, ring, kSuiteRingReads, size)}; },
              [&](const PathProgram& program) {
                  return gpuMippedPrefilter(run.vulkan, program, cube, size, [&](auto& kernel, auto& envMap, auto& sampler, auto& out) {
                      kernels::runPrefilterRing(kernel, envMap, sampler, out, 0, parameters);
                  });
              },
              [&](const OpenGlForm& form) { return glMippedPrefilter(run.gl, form, cube, parameters.members(), size); });
}

} // namespace

void addFilteredOutputs(SuiteRun& run) {
    const auto& options = run.options;
    const uint32_t size = options.prefilterSize, samples = options.sampleCount;
    const auto cube = environmentCube(options.environment, options.environmentSize, uint32_t(std::bit_width(options.environmentSize)));
    const reference::MippedEnvironment source(cube);
    for (const float roughness : options.roughnesses) {
        addOutput(run, {"PrefilterFilteredCS", fmt::format("prefilter {}² r={} from every mip", size, roughness),
                        filteredBounds()},
                  [&] { return References{reference::referenceFilteredPrefilter<float>(source, roughness, size, samples),
                   reference::referenceFilteredPrefilter<double>(source, double(roughness), size, samples)}; },
                  [&](const PathProgram& program) {
                      return gpuMippedPrefilter(run.vulkan, program, cube, size, [&](auto& kernel, auto& envMap, auto& sampler, auto& out) {
                          kernels::runPrefilter(kernel, envMap, sampler, out, 0, {roughness});
                      });
                  },
                  [&](const OpenGlForm& form) {
                      return glMippedPrefilter(run.gl, form, cube, kernels::PrefilterParameters{roughness}.members(), size);
                  });
        const auto table = reference::prefilterSampleTable(roughness, samples, cube.size);
        addOutput(run, {"PrefilterTableCS", fmt::format("prefilter {}² r={}, {} table samples", size, roughness, table.size()),
                        tableBounds()},
                  [&] { return References{reference::referenceTablePrefilter<float>(source, table, size),
                   reference::referenceTablePrefilter<double>(source, table, size)}; },
                  [&](const PathProgram& program) { return gpuTablePrefilter(run.vulkan, program, cube, table, size); },
                  [&](const OpenGlForm& form) { return glTablePrefilter(run.gl, form, cube, table, size); });
        const auto reads = reference::fitPyramidReads(roughness, kSuitePyramidReads, cube.size);
        const auto parameters = kernels::pyramidParameters(reads, kSuitePyramidReads);
        addOutput(run, {"PrefilterPyramidCS", fmt::format("prefilter {}² r={}, {} pyramid reads", size, roughness, reads.size()),
                        pyramidBounds()},
                  [&] { return References{reference::referencePyramidPrefilter<float>(source, reads, size),
                   reference::referencePyramidPrefilter<double>(source, reads, size)}; },
                  [&](const PathProgram& program) {
                      return gpuMippedPrefilter(run.vulkan, program, cube, size, [&](auto& kernel, auto& envMap, auto& sampler, auto& out) {
                          kernels::runPrefilterPyramid(kernel, envMap, sampler, out, 0, parameters);
                      });
                  },
                  [&](const OpenGlForm& form) { return glMippedPrefilter(run.gl, form, cube, parameters.members(), size); });
        if (const auto ring = reference::pyramidRing(roughness, cube.size)) addRingOutput(run, cube, source, *ring, roughness);
    }
}

} // namespace iblkit::consistency
