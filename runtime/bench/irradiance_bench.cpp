#include "measurements.hpp"

#include "gpu_steps.hpp"
#include "reference_irradiance.hpp"

#include <fmt/core.h>

#include <cmath>
#include <optional>

namespace iblkit::bench {
namespace {

// The exact sum (Lambert's formula on the texels a normal's horizon cuts) reads the source at
// most this size: 6·128² texels per irradiance texel keep the reference to seconds.
constexpr uint32_t kReferenceSourceLimit = 128;

} // namespace

BenchResult measureIrradiance(const vulkan::VulkanContext& context, vulkan::Image& source, const reference::MippedCube& cube,
                              const BenchOptions& options, const ReferenceCache& cache) {
    const uint32_t mip = bake::firstMipAtMost(cube.size, kReferenceSourceLimit);
    const uint32_t sourceSize = cube.size >> mip, size = options.irradianceSize;
    const auto texels = cube.mip(mip);
    const auto key = ReferenceCache::key(fmt::format("exact irradiance v2 (Lambert's clipped texels) source {} output {}", sourceSize, size),
                                         std::as_bytes(texels));
    const auto reference = cache.getOrCompute(key, size_t(6) * size * size * 3, [&] {
        return flatten(reference::exactIrradianceCube(std::vector<float>(texels.begin(), texels.end()), sourceSize, size));
    });
    bake::IrradianceKernels steps(context);
    std::optional<bake::Irradiance> irradiance;
    const auto timing = timeRepeated(options.repeat, [&] {
        bake::BakeProgress progress(true);
        irradiance.emplace(bake::computeIrradiance(context, steps, source, size, progress));
        return progress.steps().back().deviceMilliseconds;
    });
    const auto values = irradiance->cube.download(context);
    ErrorSummary errors;
    const auto exact = unflatten(reference);
    for (size_t i = 0; i < exact.size(); ++i)
        errors.add(relativeLuminanceError({values[4 * i], values[4 * i + 1], values[4 * i + 2]}, exact[i]));
    return {BenchOutput::Irradiance, {}, "exact-sum", 0, 0, timing.deviceMilliseconds, timing.wallMilliseconds,
            options.repeat, errors.rms(), errors.max(), {}};
}

} // namespace iblkit::bench
