#include "render/split_sum_render.hpp"

#include "buffer.hpp"
#include "kernels/kernel_steps.hpp"
#include "shading_maps.hpp"

namespace iblkit::render {

kernels::RenderSplitSumParameters splitSumParameters(const SphereGrid& grid, const BakedMaps& maps, uint32_t cellSize) {
    return {grid.columns(), cellSize, maps.schedule.mips,
            bake::recipeParameters(*maps.recipe, maps.schedule, maps.lights.size(), maps.lightLevel),
            uint32_t(maps.recipe->glass.transmission), float(maps.recipe->glass.roughnessScale)};
}

SphereImage renderSplitSum(const vulkan::VulkanContext& context, kernels::Kernel& kernel, const SphereGrid& grid,
                           BakedMaps& maps, uint32_t cellSize, bake::BakeProgress& progress) {
    progress.begin("split sum");
    const uint32_t width = grid.columns() * cellSize, height = grid.rowCount() * cellSize;
    vulkan::Image image(context, {"SplitSum", &vulkan::texelFormatNamed("R32G32B32A32_SFLOAT"), width, height, 1, 1, false, true});
    const vulkan::Sampler linear(context, {});
    const auto materials = packSpheres(grid);
    const auto spheres = vulkan::storageBuffer(context, std::as_bytes(std::span(materials)), "Spheres");
    auto glass = bake::glassTables(context, maps.recipe->glass.transmission);
    kernels::runRenderSplitSum(kernel, {spheres, maps.specular, maps.irradiance.cube, maps.lut, maps.lobeTable, glass.transmission,
                                        glass.sphere, *maps.lightBuffer, linear, image},
                               splitSumParameters(grid, maps, cellSize));
    progress.addDeviceTime(kernel.takeTotals().deviceMilliseconds);
    SphereImage result{width, height, image.download(context)};
    progress.end();
    return result;
}

} // namespace iblkit::render
