#include "bake_kernels.hpp"

namespace iblkit::bake {

BakeKernels::BakeKernels(const vulkan::VulkanContext& context, const BakeSettings& settings) {
    // Two threads for two cores, each in the order the bake needs its kernels.
    specularFuture_ = std::async(std::launch::async, [&context, method = settings.specularMethod,
                                                      samples = resolvedSamples(settings)] {
        auto specular = std::make_unique<kernels::SpecularMethod>(context, method, samples);
        auto preview = std::make_unique<kernels::Kernel>(makeKernel(context, kernels::KernelRole::Preview));
        return Specular{std::move(specular), std::move(preview)};
    });
    lutFuture_ = std::async(std::launch::async, [&context, method = settings.lutMethod,
                                                 count = resolvedLutSamples(settings)] {
        auto lut = std::make_unique<kernels::LutMethod>(context, method, count);
        return Lut{std::move(lut), std::make_unique<IrradianceKernels>(context)};
    });
}

BakeKernels::Specular& BakeKernels::specularReady() {
    if (!specular_) specular_ = specularFuture_.get();
    return *specular_;
}

BakeKernels::Lut& BakeKernels::lutReady() {
    if (!lut_) lut_ = lutFuture_.get();
    return *lut_;
}

kernels::SpecularMethod& BakeKernels::specular() { return *specularReady().method; }
kernels::Kernel& BakeKernels::preview() { return *specularReady().preview; }
kernels::LutMethod& BakeKernels::lut() { return *lutReady().method; }
IrradianceKernels& BakeKernels::irradiance() { return *lutReady().irradiance; }

} // namespace iblkit::bake
