#include "kernels/table_method.hpp"

#include "kernels/kernel_steps.hpp"
#include "kernels/sampled_methods.hpp"
#include "prefilter_sample_table.hpp"

#include <algorithm>
#include <stdexcept>

namespace iblkit::kernels {
namespace {

uint32_t checkedSamples(uint32_t samples) {
    if (samples == 0 || samples > kLoopLimit)
        throw std::invalid_argument("the sample-table method takes 1 to " + std::to_string(kLoopLimit) +
                                    " samples, not " + std::to_string(samples));
    return samples;
}

} // namespace

uint32_t tableSamplesAt(uint32_t samples, uint32_t mip) {
    const uint32_t growth = mip > 0 ? mip - 1 : 0;
    return uint32_t(std::min<uint64_t>(uint64_t(samples) << std::min(growth, 16u), kLoopLimit));
}

TablePrefilter::TablePrefilter(const vulkan::VulkanContext& context, const std::string& method, uint32_t samples,
                               const ShaderFiles& files)
    : samples_(checkedSamples(samples)),
      kernel_(context, compileKernel(kernelFor(KernelRole::PrefilterTable, method), {}, {}, files)) {}

void TablePrefilter::run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip,
                         float roughness) {
    const auto table = reference::prefilterSampleTable(roughness, tableSamplesAt(samples_, mip), source.desc().width);
    const auto bytes = std::as_bytes(std::span(table));
    vulkan::Buffer buffer(kernel_.context(), bytes.size(), vk::BufferUsageFlagBits::eStorageBuffer, "SampleTable");
    buffer.write(bytes);
    runPrefilterTable(kernel_, source, sampler, buffer, uint32_t(table.size()), target, mip);
}

} // namespace iblkit::kernels
