#pragma once

#include "kernels/kernel.hpp"

#include "image.hpp"
#include "kernels/kernel_parameters.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::reference {
struct PyramidRead;
struct PyramidRing;
}

namespace iblkit::kernels {

// PrefilterPyramidCS's parameters for `reads` (reference::fitPyramidReads's) in a shader
// compiled with READ_COUNT = readCount, at least as many.
PrefilterPyramidParameters pyramidParameters(const std::vector<reference::PyramidRead>& reads, uint32_t readCount);
// PrefilterRingCS's parameters for `ring`.
PrefilterRingParameters ringParameters(const reference::PyramidRing& ring);
// PrefilterRingCS as `method` has it, with reference::kPyramidRingReads reads around the ring.
KernelProgram compileRingKernel(const std::string& method, const ShaderFiles& files);
// Runs `ring` on mip `mip` of `target` where the lobe at `roughness` is wide enough for a ring
// (reference::pyramidRing); returns false, having run nothing, where it is not.
bool runRingWhereWide(Kernel& ring, vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target,
                      uint32_t mip, float roughness);

// The pyramid method: per mip, reads of the source's mip chain along each texel's normal, their
// lods and weights fitted on the host to the GGX lobe (reference::fitPyramidReads), or, for a
// lobe too wide for them (reference::pyramidRing), one read along the normal and a ring of reads
// around it (PrefilterRingCS). `reads` is the most reads per texel along the normal, 1 to 4;
// throws std::invalid_argument otherwise.
class PyramidPrefilter {
public:
    PyramidPrefilter(const vulkan::VulkanContext& context, const std::string& method, uint32_t reads,
                     const ShaderFiles& files = embeddedShaderFiles());
    // Writes mip `mip` of `target` (RGBA32F, storage) from `source` (with its mip chain, read
    // through `sampler`) at `roughness`.
    void run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip, float roughness);
    DispatchTotals takeTotals();

private:
    uint32_t reads_;
    Kernel kernel_, ring_;
};

} // namespace iblkit::kernels
