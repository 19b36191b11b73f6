#pragma once

#include "kernels/kernel.hpp"

#include "image.hpp"

#include <cstdint>
#include <string>

namespace iblkit::kernels {

// Whether the mip chain copies the source's mip at `roughness` (on a cube of sourceSize² faces)
// rather than running the ring: where reference::pyramidRing gives none.
bool mipChainCopies(float roughness, uint32_t sourceSize);

// The mip-chain method, the cheapest of all: where the lobe is narrow (no reference::pyramidRing
// for its roughness), a mip is the source's own box-filtered mip of that level, copied with no
// shader; where it is wide, the pyramid's ring (PrefilterRingCS), because a box mip would keep a
// small sun in one bright texel where the lobe spreads it over a hemisphere. It takes no count.
class MipChainPrefilter {
public:
    MipChainPrefilter(const vulkan::VulkanContext& context, const std::string& method,
                      const ShaderFiles& files = embeddedShaderFiles());
    // Writes mip `mip` of `target` (RGBA32F, storage, its mips the sizes of `source`'s) from
    // `source` (with its mip chain, read through `sampler`) at `roughness`.
    void run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip, float roughness);
    // The ring's dispatches and the copies, timed the same way.
    DispatchTotals takeTotals();

private:
    const vulkan::VulkanContext& context_;
    Kernel ring_;
    DispatchTotals copies_;
};

} // namespace iblkit::kernels
