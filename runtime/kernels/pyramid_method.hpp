#pragma once

#include "kernels/kernel.hpp"

#include "image.hpp"
#include "kernels/kernel_parameters.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::reference {
struct PyramidRead;
}

namespace iblkit::kernels {

// PrefilterPyramidCS's parameters for `reads` (reference::fitPyramidReads's) in a shader
// compiled with READ_COUNT = readCount, at least as many.
PrefilterPyramidParameters pyramidParameters(const std::vector<reference::PyramidRead>& reads, uint32_t readCount);

// The pyramid method: per mip, reads of the source's mip chain along each texel's normal, their
// lods and weights fitted on the host to the GGX lobe (reference::fitPyramidReads). `reads` is
// the most reads per texel, 1 to 4; throws std::invalid_argument otherwise.
class PyramidPrefilter {
public:
    PyramidPrefilter(const vulkan::VulkanContext& context, const std::string& method, uint32_t reads,
                     const ShaderFiles& files = embeddedShaderFiles());
    // Writes mip `mip` of `target` (RGBA32F, storage) from `source` (with its mip chain, read
    // through `sampler`) at `roughness`.
    void run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip, float roughness);
    DispatchTotals takeTotals() { return kernel_.takeTotals(); }

private:
    uint32_t reads_;
    Kernel kernel_;
};

} // namespace iblkit::kernels
