#pragma once

#include "render/baked_maps.hpp"
#include "render/sphere_images.hpp"

#include "kernels/kernel.hpp"

namespace iblkit::render {

// SplitSumSpheresCS: the sphere grid shaded with `maps`, linear, alpha the coverage.
SphereImage renderSplitSum(const vulkan::VulkanContext& context, kernels::Kernel& kernel, BakedMaps& maps,
                           uint32_t cellSize, bake::BakeProgress& progress);

} // namespace iblkit::render
