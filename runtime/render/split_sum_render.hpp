#pragma once

#include "render/baked_maps.hpp"
#include "render/sphere_grid.hpp"
#include "render/sphere_images.hpp"

#include "kernels/kernel.hpp"

namespace iblkit::render {

// SplitSumSpheresCS's parameters for `maps` as their recipe reads them.
kernels::RenderSplitSumParameters splitSumParameters(const SphereGrid& grid, const BakedMaps& maps, uint32_t cellSize);

// SplitSumSpheresCS: the sphere grid shaded with `maps`, linear, alpha the coverage.
SphereImage renderSplitSum(const vulkan::VulkanContext& context, kernels::Kernel& kernel, const SphereGrid& grid,
                           BakedMaps& maps, uint32_t cellSize, bake::BakeProgress& progress);

} // namespace iblkit::render
