#include "kernels/grid_lut_method.hpp"

#include "kernels/kernel_steps.hpp"
#include "kernels/lut_methods.hpp"

#include <stdexcept>
#include <string>

namespace iblkit::kernels {
namespace {

uint32_t checkedGrid(uint32_t gridSize) {
    if (gridSize < kMinLutGrid || gridSize > kMaxLutGrid)
        throw std::invalid_argument("the quadrature-grid LUT takes " + std::to_string(kMinLutGrid) + " to " +
                                    std::to_string(kMaxLutGrid) + " grid nodes per side, not " + std::to_string(gridSize));
    return gridSize;
}

} // namespace

KernelProgram compileGridLutNodes(uint32_t nodes, const ShaderFiles& files) {
    if (nodes == 0 || nodes > kMaxQuadratureNodes)
        throw std::invalid_argument("the quadrature takes 1 to " + std::to_string(kMaxQuadratureNodes) +
                                    " nodes per panel, not " + std::to_string(nodes));
    return compileKernel(kernelFor(KernelRole::BrdfLutGrid, kQuadratureGridLutMethod),
                         {{"SAMPLE_COUNT", std::to_string(nodes)}}, {}, files);
}

KernelProgram compileGridLutResample(const ShaderFiles& files) {
    return compileKernel(kernelFor(KernelRole::BrdfLutResample, kQuadratureGridLutMethod), {}, {{"Precomputed", "rg32f"}},
                         files);
}

GridLut::GridLut(const vulkan::VulkanContext& context, uint32_t gridSize, uint32_t nodes, const ShaderFiles& files)
    : gridSize_(checkedGrid(gridSize)), nodes_(context, compileGridLutNodes(nodes, files)),
      resample_(context, compileGridLutResample(files)) {}

void GridLut::run(vulkan::Image& lut) {
    const vulkan::Buffer grid(nodes_.context(), vk::DeviceSize(gridSize_) * gridSize_ * 2 * sizeof(float),
                              vk::BufferUsageFlagBits::eStorageBuffer, "Grid");
    runBrdfLutGrid(nodes_, grid, gridSize_);
    runBrdfLutResample(resample_, grid, gridSize_, lut);
}

DispatchTotals GridLut::takeTotals() {
    auto totals = nodes_.takeTotals();
    totals += resample_.takeTotals();
    return totals;
}

} // namespace iblkit::kernels
