#include "kernels/pyramid_method.hpp"

#include "kernels/kernel_steps.hpp"
#include "pyramid_fit.hpp"
#include "pyramid_ring.hpp"

#include <stdexcept>

namespace iblkit::kernels {
namespace {

uint32_t checkedReads(uint32_t reads) {
    if (reads == 0 || reads > reference::kMaxPyramidReads)
        throw std::invalid_argument("the pyramid method takes 1 to " + std::to_string(reference::kMaxPyramidReads) +
                                    " reads per texel, not " + std::to_string(reads));
    return reads;
}

} // namespace

PrefilterPyramidParameters pyramidParameters(const std::vector<reference::PyramidRead>& reads, uint32_t readCount) {
    PrefilterPyramidParameters parameters;
    for (const auto& read : reads) {
        parameters.lods.push_back(read.lod);
        parameters.weights.push_back(read.weight);
    }
    // The shader makes READ_COUNT reads: the fit's unused ones read mip 0 with no weight.
    parameters.lods.resize(readCount, 0.f);
    parameters.weights.resize(readCount, 0.f);
    return parameters;
}

PrefilterRingParameters ringParameters(const reference::PyramidRing& ring) {
    return {ring.centreLod, ring.ringLod, ring.cosAngle, ring.centreWeight};
}

KernelProgram compileRingKernel(const std::string& method, const ShaderFiles& files) {
    return compileKernel(kernelFor(KernelRole::PrefilterRing, method),
                         {{"RING_COUNT", std::to_string(reference::kPyramidRingReads)}}, {}, files);
}

bool runRingWhereWide(Kernel& ring, vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target,
                      uint32_t mip, float roughness) {
    const auto wide = reference::pyramidRing(roughness, source.desc().width);
    if (wide) runPrefilterRing(ring, source, sampler, target, mip, ringParameters(*wide));
    return wide.has_value();
}

PyramidPrefilter::PyramidPrefilter(const vulkan::VulkanContext& context, const std::string& method, uint32_t reads,
                                   const ShaderFiles& files)
    : reads_(checkedReads(reads)),
      kernel_(context, compileKernel(kernelFor(KernelRole::PrefilterPyramid, method),
                                     {{"READ_COUNT", std::to_string(reads)}}, {}, files)),
      ring_(context, compileRingKernel(method, files)) {}

void PyramidPrefilter::run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip,
                           float roughness) {
    if (runRingWhereWide(ring_, source, sampler, target, mip, roughness)) return;
    const auto reads = reference::fitPyramidReads(roughness, reads_, source.desc().width);
    runPrefilterPyramid(kernel_, source, sampler, target, mip, pyramidParameters(reads, reads_));
}

DispatchTotals PyramidPrefilter::takeTotals() {
    auto totals = kernel_.takeTotals();
    totals += ring_.takeTotals();
    return totals;
}

} // namespace iblkit::kernels
