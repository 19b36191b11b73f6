#include "gpu_bake.hpp"

#include "kernels/kernel_steps.hpp"
#include "suite_inputs.hpp"

namespace iblkit::consistency {
namespace {

const vulkan::TexelFormat& rg32() { return vulkan::texelFormatNamed("R32G32_SFLOAT"); }

vulkan::Image uploadEnvironment(const vulkan::VulkanContext& context, const reference::CubeEnvironment& environment) {
    vulkan::Image envMap(context, {"EnvMap", &vulkan::rgba32Float(), environment.size(), environment.size(), 6, 1, true, false});
    envMap.upload(context, environment.texels());
    return envMap;
}

} // namespace

std::vector<float> gpuBrdfLut(const vulkan::VulkanContext& context, const PathProgram& program, uint32_t size) {
    kernels::Kernel kernel(context, program);
    vulkan::Image lut(context, {"Precomputed", &rg32(), size, size, 1, 1, false, true});
    kernels::runBrdfLut(kernel, lut);
    return lut.download(context);
}

std::vector<float> gpuPrefilter(const vulkan::VulkanContext& context, const PathProgram& program,
                                const reference::CubeEnvironment& environment, float roughness, uint32_t size) {
    kernels::Kernel kernel(context, program);
    auto envMap = uploadEnvironment(context, environment);
    const vulkan::Sampler linear(context, {});
    vulkan::Image prefiltered(context, {"Prefiltered", &vulkan::rgba32Float(), size, size, 6, 1, false, true});
    kernels::runPrefilter(kernel, envMap, linear, prefiltered, 0, {roughness});
    return prefiltered.download(context);
}

std::vector<float> gpuBrdfLutChunks(const vulkan::VulkanContext& context, const PathProgram& program, uint32_t size,
                                    uint32_t samples, uint32_t chunk) {
    kernels::Kernel kernel(context, program);
    vulkan::Image lut(context, {"Precomputed", &rg32(), size, size, 1, 1, false, true});
    kernels::runBrdfLutChunked(kernel, lut, samples, chunk);
    return lut.download(context);
}

std::vector<float> gpuPrefilterChunks(const vulkan::VulkanContext& context, const PathProgram& program,
                                      const reference::CubeEnvironment& environment, float roughness, uint32_t size,
                                      uint32_t samples, uint32_t chunk) {
    kernels::Kernel kernel(context, program);
    auto envMap = uploadEnvironment(context, environment);
    const vulkan::Sampler linear(context, {});
    vulkan::Image prefiltered(context, {"Prefiltered", &vulkan::rgba32Float(), size, size, 6, 1, false, true});
    kernels::runPrefilterChunked(kernel, envMap, linear, prefiltered, 0, roughness, samples, chunk);
    return prefiltered.download(context);
}

} // namespace iblkit::consistency
