#pragma once

#include "kernels/kernel.hpp"

#include "image.hpp"

#include <cstdint>
#include <string>

namespace iblkit::kernels {

// The table's samples at `mip` for `samples` at mip 1: twice the mip below's, to the loop limit
// (a mip has a quarter of the texels and a wider lobe, whose error falls about as 1 / samples).
uint32_t tableSamplesAt(uint32_t samples, uint32_t mip);

// The sample-table method: per mip, the samples' directions, weights and lods computed on the
// host in double (reference::prefilterSampleTable) and shared by every texel of the mip. Throws
// std::invalid_argument for 0 samples or more than the loop limit (the shader's loop runs once
// per entry).
class TablePrefilter {
public:
    TablePrefilter(const vulkan::VulkanContext& context, const std::string& method, uint32_t samples,
                   const ShaderFiles& files = embeddedShaderFiles());
    // Writes mip `mip` of `target` (RGBA32F, storage) from `source` (with its mip chain, read
    // through `sampler`) at `roughness`.
    void run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip, float roughness);
    DispatchTotals takeTotals() { return kernel_.takeTotals(); }

private:
    uint32_t samples_;
    Kernel kernel_;
};

} // namespace iblkit::kernels
