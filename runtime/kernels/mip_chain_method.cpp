#include "kernels/mip_chain_method.hpp"

#include "kernels/pyramid_method.hpp"
#include "pyramid_ring.hpp"

#include <algorithm>
#include <utility>

namespace iblkit::kernels {

MipChainPrefilter::MipChainPrefilter(const vulkan::VulkanContext& context, const std::string& method,
                                     const ShaderFiles& files)
    : context_(context),
      ring_(context, compileRingKernel(method, files)) {}

bool mipChainCopies(float roughness, uint32_t sourceSize) { return !reference::pyramidRing(roughness, sourceSize); }

void MipChainPrefilter::run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip,
                            float roughness) {
    if (runRingWhereWide(ring_, source, sampler, target, mip, roughness)) return;
    const auto copy = target.copyMipFrom(context_, source, mip);
    copies_ += {std::max(0.0, copy.deviceMilliseconds), copy.wallMilliseconds, 1};
}

DispatchTotals MipChainPrefilter::takeTotals() {
    auto totals = ring_.takeTotals();
    totals += std::exchange(copies_, {});
    return totals;
}

} // namespace iblkit::kernels
