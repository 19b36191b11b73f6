#pragma once

#include "bake_plan.hpp"
#include "bake_settings.hpp"
#include "gpu_steps.hpp"
#include "kernels/kernel.hpp"
#include "kernels/lut_methods.hpp"
#include "kernels/specular_method.hpp"

#include <filesystem>
#include <future>
#include <memory>
#include <optional>

namespace iblkit::bake {

// Every kernel a bake runs after its source cube, compiled and made on two worker threads while
// the input loads and the source cube is built. Measured on lavapipe, the compiles sat between
// the dispatches otherwise: 55 ms for the quadrature grid's node kernel alone, about 150 ms in all.
// Each getter waits for its kernels; the destructor waits for both threads. The prefilter and the
// LUT are compiled only where `outputs` needs them: their getters give null otherwise.
// `sourceSize`, where known, is the source cube's width, for which the prefilter compiles first.
class BakeKernels {
public:
    BakeKernels(const vulkan::VulkanContext& context, const ResolvedSettings& settings, const NeededOutputs& outputs = {},
                uint32_t sourceSize = 0);

    kernels::SpecularMethod* specular();
    kernels::Kernel& preview();
    kernels::Kernel& downsample(); // DownsampleCubeCS, for a cube made on the host
    kernels::LutMethod* lut();
    IrradianceKernels& irradiance();
    // The two threads' compile times, summed (each thread's wall time from its start to its last kernel).
    double compileMilliseconds();

private:
    struct Specular {
        double milliseconds = 0;
        std::unique_ptr<kernels::SpecularMethod> method;
        std::unique_ptr<kernels::Kernel> preview;
        std::unique_ptr<kernels::Kernel> downsample;
    };
    struct Lut {
        double milliseconds = 0;
        std::unique_ptr<kernels::LutMethod> method;
        std::unique_ptr<IrradianceKernels> irradiance;
    };
    Specular& specularReady();
    Lut& lutReady();

    std::future<Specular> specularFuture_;
    std::future<Lut> lutFuture_;
    std::optional<Specular> specular_;
    std::optional<Lut> lut_;
};

// Compiles every kernel of a bake with the default settings (any input, any scene, any profile) into
// the content store at `folder`, for the program's built-in kernels (kernels/built_in_kernels.hpp):
// `iblkit-program precompile-kernels` runs it as the program is built. Needs no device.
void precompileBakeKernels(const std::filesystem::path& folder);

} // namespace iblkit::bake
