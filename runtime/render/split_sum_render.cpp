#include "render/split_sum_render.hpp"

#include "render/render_settings.hpp"

#include "kernels/kernel_steps.hpp"

namespace iblkit::render {

SphereImage renderSplitSum(const vulkan::VulkanContext& context, kernels::Kernel& kernel, BakedMaps& maps,
                           uint32_t cellSize, bake::BakeProgress& progress) {
    progress.begin("split sum");
    const uint32_t width = kColumns * cellSize, height = kRows * cellSize;
    vulkan::Image image(context, {"SplitSum", &vulkan::texelFormatNamed("R32G32B32A32_SFLOAT"), width, height, 1, 1, false, true});
    const vulkan::Sampler linear(context, {});
    kernels::runRenderSplitSum(kernel, maps.specular, maps.irradiance.cube, maps.lut, linear, image,
                               {kColumns, kMetalRows, cellSize, maps.specular.desc().mips});
    progress.addDeviceTime(kernel.takeTotals().deviceMilliseconds);
    SphereImage result{width, height, image.download(context)};
    progress.end();
    return result;
}

} // namespace iblkit::render
