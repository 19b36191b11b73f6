#include "gpu_cube_bake.hpp"

#include "shading/lobe_table.hpp"

namespace iblkit::consistency {
namespace {


vulkan::Image uploadCube(const vulkan::VulkanContext& context, const std::string& name, const MippedCube& cube) {
    vulkan::Image image(context, {name, &vulkan::rgba32Float(), cube.size, cube.size, 6, cube.mips, true, false});
    image.upload(context, cube.texels);
    return image;
}

} // namespace

std::vector<float> gpuSkyCube(const vulkan::VulkanContext& context, const PathProgram& program, uint32_t size,
                              uint32_t supersample) {
    kernels::Kernel kernel(context, program);
    vulkan::Image cube(context, {"Cube", &vulkan::rgba32Float(), size, size, 6, 1, true, true});
    kernels::runSkyCube(kernel, cube, {supersample});
    return cube.download(context);
}

std::vector<float> gpuEquirectToCube(const vulkan::VulkanContext& context, const PathProgram& program,
                                     const Panorama& panorama, uint32_t size, uint32_t supersample) {
    kernels::Kernel kernel(context, program);
    vulkan::Image equirect(context, {"Equirect", &vulkan::rgba32Float(), panorama.width, panorama.height, 1, 1, false, false});
    equirect.upload(context, panorama.texels);
    vulkan::Image cube(context, {"Cube", &vulkan::rgba32Float(), size, size, 6, 1, true, true});
    kernels::runEquirectToCube(kernel, equirect, cube, {supersample});
    return cube.download(context);
}

std::vector<float> gpuDownsampleChain(const vulkan::VulkanContext& context, const PathProgram& program,
                                      const MippedCube& cube) {
    kernels::Kernel kernel(context, program);
    vulkan::Image image(context, {"Source", &vulkan::rgba32Float(), cube.size, cube.size, 6, cube.mips, true, true});
    std::vector<float> values(image.valueCount(), 0.f);
    const auto mip0 = cube.mip(0);
    std::copy(mip0.begin(), mip0.end(), values.begin());
    image.upload(context, values);
    kernels::runDownsampleChain(kernel, image);
    const auto chain = image.download(context);
    return {chain.begin() + std::ptrdiff_t(image.valueOffset(1, 0)), chain.end()};
}

kernels::ShProjection gpuShProject(const vulkan::VulkanContext& context, const PathProgram& program,
                                   const MippedCube& cube, uint32_t mip) {
    kernels::Kernel kernel(context, program);
    auto source = uploadCube(context, "Source", cube);
    return kernels::runShProject(context, kernel, source, mip);
}

std::vector<float> gpuIrradianceCube(const vulkan::VulkanContext& context, const PathProgram& program,
                                     const std::vector<float>& moments, uint32_t momentSize, uint32_t outSize) {
    kernels::Kernel kernel(context, program);
    const auto buffer = vulkan::storageBuffer(context, std::as_bytes(std::span(moments)), "Moments");
    vulkan::Image irradiance(context, {"Irradiance", &vulkan::rgba32Float(), outSize, outSize, 6, 1, true, true});
    kernels::runIrradianceCube(kernel, buffer, momentSize, irradiance);
    return irradiance.download(context);
}

std::vector<float> gpuMippedPrefilter(const vulkan::VulkanContext& context, const PathProgram& program,
                                      const MippedCube& cube, uint32_t size, const MippedDispatch& dispatch) {
    kernels::Kernel kernel(context, program);
    auto envMap = uploadCube(context, "EnvMap", cube);
    const vulkan::Sampler linear(context, {});
    vulkan::Image prefiltered(context, {"Prefiltered", &vulkan::rgba32Float(), size, size, 6, 1, false, true});
    dispatch(kernel, envMap, linear, prefiltered);
    return prefiltered.download(context);
}

std::vector<float> gpuTablePrefilter(const vulkan::VulkanContext& context, const PathProgram& program,
                                     const MippedCube& cube, std::span<const glm::vec4> table, uint32_t size) {
    kernels::Kernel kernel(context, program);
    auto envMap = uploadCube(context, "EnvMap", cube);
    const vulkan::Sampler linear(context, {});
    const auto bytes = std::as_bytes(table);
    vulkan::Buffer samples(context, bytes.size(), vk::BufferUsageFlagBits::eStorageBuffer, "SampleTable");
    samples.write(bytes);
    vulkan::Image prefiltered(context, {"Prefiltered", &vulkan::rgba32Float(), size, size, 6, 1, false, true});
    kernels::runPrefilterTable(kernel, envMap, linear, samples, uint32_t(table.size()), prefiltered, 0);
    return prefiltered.download(context);
}

GpuShadingMaps uploadShadingMaps(const vulkan::VulkanContext& context, const PreviewInputs& inputs) {
    const auto& rg32 = vulkan::texelFormatNamed("R32G32_SFLOAT");
    const uint32_t tableSize = shading::kLobeTableSize;
    GpuShadingMaps maps{uploadCube(context, "Specular", inputs.specular), uploadCube(context, "IrradianceMap", inputs.irradiance),
                        vulkan::Image(context, {"BrdfLut", &rg32, inputs.lutSize, inputs.lutSize, 1, 1, false, false}),
                        vulkan::Image(context, {"LobeTable", &vulkan::rgba32Float(), tableSize, tableSize, 1, 1, false, false}),
                        vulkan::storageBuffer(context, std::as_bytes(std::span(inputs.lights)), "Lights")};
    maps.lut.upload(context, inputs.lut);
    maps.lobeTable.upload(context, inputs.lobeTable);
    return maps;
}

std::vector<float> gpuPreview(const vulkan::VulkanContext& context, const PathProgram& program,
                              const PreviewInputs& inputs) {
    kernels::Kernel kernel(context, program);
    auto maps = uploadShadingMaps(context, inputs);
    const vulkan::Sampler linear(context, {});
    vulkan::Image preview(context, {"Preview", &vulkan::rgba32Float(), inputs.width, inputs.height, 1, 1, false, true});
    kernels::runPreview(kernel, {maps.specular, maps.irradiance, maps.lut, maps.lobeTable, maps.lights, linear, preview},
                        inputs.parameters);
    return preview.download(context);
}

} // namespace iblkit::consistency
