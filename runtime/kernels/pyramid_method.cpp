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

PyramidPrefilter::PyramidPrefilter(const vulkan::VulkanContext& context, const std::string& method, uint32_t reads,
                                   const ShaderFiles& files)
    : reads_(checkedReads(reads)),
      kernel_(context, compileKernel(kernelFor(KernelRole::PrefilterPyramid, method),
                                     {{"READ_COUNT", std::to_string(reads)}}, {}, files)),
      ring_(context, compileKernel(kernelFor(KernelRole::PrefilterRing, method),
                                   {{"RING_COUNT", std::to_string(reference::kPyramidRingReads)}}, {}, files)) {}

void PyramidPrefilter::run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip,
                           float roughness) {
    const uint32_t size = source.desc().width;
    if (const auto ring = reference::pyramidRing(roughness, size))
        runPrefilterRing(ring_, source, sampler, target, mip, ringParameters(*ring));
    else
        runPrefilterPyramid(kernel_, source, sampler, target, mip,
                            pyramidParameters(reference::fitPyramidReads(roughness, reads_, size), reads_));
}

DispatchTotals PyramidPrefilter::takeTotals() {
    auto totals = kernel_.takeTotals();
    totals += ring_.takeTotals();
    return totals;
}

} // namespace iblkit::kernels
