#pragma once

#include "kernels/kernel.hpp"

#include "image.hpp"

#include <cstdint>

namespace iblkit::kernels {

// GridLut's two kernels: the nodes' at `nodes` per panel (std::invalid_argument outside
// 1..kMaxQuadratureNodes), and the resampling.
KernelProgram compileGridLutNodes(uint32_t nodes, const ShaderFiles& files = embeddedShaderFiles());
KernelProgram compileGridLutResample(const ShaderFiles& files = embeddedShaderFiles());

// The quadrature-grid LUT: BrdfLutGridCS integrates a gridSize² grid of nodes (Common/LutGrid.fxh)
// at `nodes` Gauss–Legendre nodes per panel, and BrdfLutResampleCS interpolates it to every
// texel of the LUT. Throws std::invalid_argument for a grid outside kMinLutGrid..kMaxLutGrid or
// nodes outside 1..kMaxQuadratureNodes.
class GridLut {
public:
    GridLut(const vulkan::VulkanContext& context, uint32_t gridSize, uint32_t nodes,
            const ShaderFiles& files = embeddedShaderFiles());
    // Writes `lut` (R32G32_SFLOAT, storage) whole.
    void run(vulkan::Image& lut);
    DispatchTotals takeTotals();

private:
    uint32_t gridSize_;
    Kernel nodes_, resample_;
};

} // namespace iblkit::kernels
