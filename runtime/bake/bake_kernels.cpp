#include "bake_kernels.hpp"

#include "kernels/compiled_kernel_cache.hpp"

namespace iblkit::bake {

BakeKernels::BakeKernels(const vulkan::VulkanContext& context, const BakeSettings& settings, const NeededOutputs& outputs) {
    // Two threads for two cores, each in the order the bake needs its kernels.
    // The workers compile with this thread's kernel cache.
    auto* cache = kernels::compiledKernelCacheInUse();
    specularFuture_ = std::async(std::launch::async, [&context, cache, method = settings.specularMethod,
                                                      samples = resolvedSamples(settings), needed = outputs.specular] {
        const kernels::UseCompiledKernelCache use(cache);
        auto specular = needed ? std::make_unique<kernels::SpecularMethod>(context, method, samples) : nullptr;
        auto preview = std::make_unique<kernels::Kernel>(makeKernel(context, kernels::KernelRole::Preview));
        return Specular{std::move(specular), std::move(preview)};
    });
    lutFuture_ = std::async(std::launch::async, [&context, cache, method = settings.lutMethod,
                                                 count = resolvedLutSamples(settings), needed = outputs.lut] {
        const kernels::UseCompiledKernelCache use(cache);
        auto lut = needed ? std::make_unique<kernels::LutMethod>(context, method, count) : nullptr;
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

kernels::SpecularMethod* BakeKernels::specular() { return specularReady().method.get(); }
kernels::Kernel& BakeKernels::preview() { return *specularReady().preview; }
kernels::LutMethod* BakeKernels::lut() { return lutReady().method.get(); }
IrradianceKernels& BakeKernels::irradiance() { return *lutReady().irradiance; }

} // namespace iblkit::bake
