#include "render/baked_maps.hpp"

#include "bake_kernels.hpp"
#include "bake_settings.hpp"

namespace iblkit::render {

BakedMaps bakeMaps(const vulkan::VulkanContext& context, const bake::EnvironmentInput& input, bake::BakeProgress& progress) {
    bake::BakeSettings defaults;
    bake::BakeKernels kernels(context, defaults);
    const uint32_t size = bake::resolvedSize(defaults, input.cubeSize);
    auto source = bake::buildSourceCube(context, input, size, progress);
    const std::vector<bool> everyMip(bake::resolvedMips(defaults, size), true);
    auto specular = bake::prefilterSpecular(context, source, everyMip, kernels.specular(), progress);
    auto lut = bake::integrateBrdfLut(context, defaults.lutSize, *kernels.lut(), progress);
    auto irradiance = bake::computeIrradiance(context, kernels.irradiance(), source, defaults.irradianceSize, progress);
    return {std::move(source), std::move(specular), std::move(lut), std::move(irradiance)};
}

} // namespace iblkit::render
