#include "convolution_bake.hpp"

#include <bit>

namespace iblkit::consistency {
namespace {

vulkan::Image cubeImage(const vulkan::VulkanContext& context, const std::string& name, uint32_t size, uint32_t mips) {
    const auto& rgba32 = vulkan::texelFormatNamed("R32G32B32A32_SFLOAT");
    return vulkan::Image(context, {name, &rgba32, size, size, 6, mips, true, true});
}

vulkan::Image pyramidImage(const vulkan::VulkanContext& context, const std::string& name, uint32_t size) {
    return cubeImage(context, name, size, uint32_t(std::bit_width(size)));
}

vulkan::Image solidAngleImage(const vulkan::VulkanContext& context, uint32_t size) {
    return vulkan::Image(context, {"TexelSolidAngle", &vulkan::texelFormatNamed("R32_SFLOAT"), size, size, 1, 1, false, true});
}

vulkan::Image uploaded(const vulkan::VulkanContext& context, const std::string& name, const MippedCube& cube) {
    auto image = cubeImage(context, name, cube.size, cube.mips);
    image.upload(context, cube.texels);
    return image;
}

} // namespace

std::vector<float> gpuClusterPyramid(const vulkan::VulkanContext& context, const PathProgram& program,
                                     const MippedCube& cube) {
    kernels::Kernel kernel(context, program);
    if (cube.size < 2) return {}; // a single texel is no block of the pyramid
    auto source = uploaded(context, "Source", cube);
    const uint32_t size = kernels::pyramidSize(cube.size);
    auto energy = pyramidImage(context, "Energy", size), centroid = pyramidImage(context, "Centroid", size),
         geometry = pyramidImage(context, "Geometry", size);
    auto solidAngle = solidAngleImage(context, cube.size);
    kernels::runClusterPyramid(kernel, source, {energy, centroid, geometry, solidAngle});
    std::vector<float> values;
    for (auto* image : {&energy, &centroid, &geometry}) {
        const auto texels = image->download(context);
        values.insert(values.end(), texels.begin(), texels.end());
    }
    return values;
}

std::vector<float> gpuPrefilterConvolution(const vulkan::VulkanContext& context, const PathProgram& program,
                                           const PyramidTexels& pyramid, uint32_t outSize,
                                           const kernels::PrefilterConvolutionParameters& parameters) {
    kernels::Kernel kernel(context, program);
    auto source = uploaded(context, "Source", pyramid.source);
    auto energy = uploaded(context, "Energy", pyramid.energy), centroid = uploaded(context, "Centroid", pyramid.centroid),
         geometry = uploaded(context, "Geometry", pyramid.geometry);
    const auto& rgba32 = vulkan::texelFormatNamed("R32G32B32A32_SFLOAT");
    vulkan::Image target(context, {"Prefiltered", &rgba32, outSize, outSize, 6, 1, false, true});
    auto solidAngle = solidAngleImage(context, pyramid.source.size);
    solidAngle.upload(context, pyramid.texelSolidAngle);
    kernels::runPrefilterConvolution(kernel, source, {energy, centroid, geometry, solidAngle, pyramid.holdsSourceTexels}, target,
                                     0, parameters);
    return target.download(context);
}

} // namespace iblkit::consistency
