#include "measurements.hpp"

#include "converged_lut.hpp"
#include "kernels/lut_methods.hpp"

#include <fmt/core.h>
#include <glm/gtc/packing.hpp>

#include <cmath>

namespace iblkit::bench {

LutBench::LutBench(const vulkan::VulkanContext& context, const BenchOptions& options, const ReferenceCache& cache)
    : context_(context), options_(options) {
    const reference::LutQuadrature quadrature;
    const auto key = ReferenceCache::key(fmt::format("converged lut v1 size {} nodes {} {}", options.lutSize,
                                                     quadrature.thetaNodes, quadrature.phiNodes),
                                         {});
    reference_ = cache.getOrCompute(key, size_t(options.lutSize) * options.lutSize * 2, [&] { return reference::convergedBrdfLut(options.lutSize, quadrature); });
}

BenchResult LutBench::measure(const std::string& method, uint32_t samples) {
    kernels::LutMethod integrator(context_, method, samples, options_.shaderFiles);
    const uint32_t size = options_.lutSize;
    vulkan::Image lut(context_, {"BrdfLut", &vulkan::texelFormatNamed("R32G32_SFLOAT"), size, size, 1, 1, false, true});
    const auto timing = timeRepeated(options_.repeat, [&] {
        integrator.run(lut);
        return integrator.takeTotals().deviceMilliseconds;
    });
    const auto values = lut.download(context_);
    ErrorSummary errors;
    uint32_t halfSteps = 0;
    for (size_t i = 0; i < values.size(); ++i) {
        errors.add(std::abs(double(values[i]) - reference_[i]));
        // Positive halves order as their bits do: the bits' difference counts the steps between them.
        const int steps = std::abs(int(glm::packHalf1x16(values[i])) - int(glm::packHalf1x16(float(reference_[i]))));
        halfSteps = std::max(halfSteps, uint32_t(steps));
    }
    return {BenchOutput::Lut, {}, method, samples, integrator.chunkSamples(), timing.deviceMilliseconds,
            timing.wallMilliseconds, options_.repeat, errors.rms(), errors.max(), {}, 0, 0, halfSteps};
}

} // namespace iblkit::bench
