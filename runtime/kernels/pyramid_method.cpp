#include "kernels/pyramid_method.hpp"

#include "kernels/kernel_steps.hpp"
#include "pyramid_fit.hpp"

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

PyramidPrefilter::PyramidPrefilter(const vulkan::VulkanContext& context, const std::string& method, uint32_t reads,
                                   const ShaderFiles& files)
    : reads_(checkedReads(reads)),
      kernel_(context, compileKernel(kernelFor(KernelRole::PrefilterPyramid, method),
                                     {{"READ_COUNT", std::to_string(reads)}}, {}, files)) {}

void PyramidPrefilter::run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip,
                           float roughness) {
    runPrefilterPyramid(kernel_, source, sampler, target, mip,
                        pyramidParameters(reference::fitPyramidReads(roughness, reads_, source.desc().width), reads_));
}

} // namespace iblkit::kernels
