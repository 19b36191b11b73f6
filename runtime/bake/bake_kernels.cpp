#include "bake_kernels.hpp"

#include "kernels/built_in_kernels.hpp"
#include "kernels/compiled_kernel_cache.hpp"
#include "kernels/convolution_method.hpp"
#include "kernels/grid_lut_method.hpp"
#include "shading_maps.hpp"

#include <chrono>
#include <stdexcept>

namespace iblkit::bake {
namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

BakeKernels::BakeKernels(const vulkan::VulkanContext& context, const ResolvedSettings& settings, const NeededOutputs& outputs,
                         uint32_t sourceSize) {
    // Two threads for two cores, each in the order the bake needs its kernels.
    // The workers compile with this thread's kernel cache, and count in its counter.
    auto* cache = kernels::compiledKernelCacheInUse();
    auto* counter = kernels::kernelCompileCounterInUse();
    specularFuture_ = std::async(std::launch::async, [&context, cache, counter, method = settings.specularMethod,
                                                      samples = settings.sampleCount, needed = outputs.specular,
                                                      sourceSize] {
        const auto start = std::chrono::steady_clock::now();
        const kernels::UseCompiledKernelCache use(cache);
        const kernels::CountKernelCompiles counting(counter);
        // The residual of a recipe's lights gets its mips first, then the prefilter reads them.
        auto downsample = std::make_unique<kernels::Kernel>(makeKernel(context, kernels::KernelRole::DownsampleCube));
        auto specular = needed ? std::make_unique<kernels::SpecularMethod>(context, method, samples,
                                                                          kernels::embeddedShaderFiles(), sourceSize)
                               : nullptr;
        auto preview = std::make_unique<kernels::Kernel>(makeKernel(context, kernels::KernelRole::Preview));
        return Specular{millisecondsSince(start), std::move(specular), std::move(preview), std::move(downsample)};
    });
    lutFuture_ = std::async(std::launch::async, [&context, cache, counter, method = settings.lutMethod,
                                                 count = settings.lutSampleCount, needed = outputs.lut] {
        const auto start = std::chrono::steady_clock::now();
        const kernels::UseCompiledKernelCache use(cache);
        const kernels::CountKernelCompiles counting(counter);
        auto lut = needed ? std::make_unique<kernels::LutMethod>(context, method, count) : nullptr;
        auto irradiance = std::make_unique<IrradianceKernels>(context);
        return Lut{millisecondsSince(start), std::move(lut), std::move(irradiance)};
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
kernels::Kernel& BakeKernels::downsample() { return *specularReady().downsample; }
kernels::LutMethod* BakeKernels::lut() { return lutReady().method.get(); }
IrradianceKernels& BakeKernels::irradiance() { return *lutReady().irradiance; }
double BakeKernels::compileMilliseconds() { return specularReady().milliseconds + lutReady().milliseconds; }

void precompileBakeKernels(const std::filesystem::path& folder) {
    std::filesystem::create_directories(folder); // a folder that cannot be made says why
    kernels::CompiledKernelCache store(folder);
    const kernels::UseCompiledKernelCache use(&store);
    const kernels::WithoutBuiltInKernels compileEveryKernel;
    using kernels::KernelRole;
    // The source cube, the residual's mips, the irradiance and the preview (gpu_steps.hpp).
    for (const auto role : {KernelRole::SkyCube, KernelRole::EquirectToCube, KernelRole::DownsampleCube, KernelRole::ShProject,
                            KernelRole::IrradianceCube, KernelRole::Preview})
        kernels::compileKernel(kernels::kernelFor(role));
    // The default prefilter (kernels/convolution_method.hpp) and LUT (kernels/grid_lut_method.hpp).
    kernels::compileKernel(kernels::kernelFor(KernelRole::ClusterCube));
    for (const bool sourceTexelsInPyramid : {true, false})
        kernels::compileConvolutionWalk(kDefaultSpecularMethod, sourceTexelsInPyramid);
    kernels::compileGridLutNodes(kernels::kDefaultQuadratureNodes);
    kernels::compileGridLutResample();
    if (store.counts().unwritable > 0) throw std::runtime_error(folder.string() + ": cannot write the built-in kernels");
}

} // namespace iblkit::bake
