#include "measurements.hpp"

#include "gpu_steps.hpp"
#include "reference_irradiance.hpp"

#include <fmt/core.h>

#include <cmath>
#include <optional>

namespace iblkit::bench {
namespace {

// The exact sum reads the source at most this size: 6·128² texels per irradiance texel keep the
// reference to seconds, and the cosine lobe is so smooth that the box filter of one more mip
// changes E by less than the float rounding of the GPU's sums.
constexpr uint32_t kReferenceSourceLimit = 128;

} // namespace

BenchResult measureIrradiance(const vulkan::VulkanContext& context, vulkan::Image& source, const SourceCube& cube,
                              const BenchOptions& options, const ReferenceCache& cache) {
    uint32_t mip = 0;
    while ((cube.size >> mip) > kReferenceSourceLimit) ++mip;
    const uint32_t sourceSize = cube.size >> mip, size = options.irradianceSize;
    const auto texels = cube.mip(mip);
    const auto key = ReferenceCache::key(fmt::format("exact irradiance v1 source {} output {}", sourceSize, size),
                                         std::as_bytes(texels));
    const auto reference = cache.getOrCompute(key, size_t(6) * size * size * 3, [&] {
        const auto rgb = reference::irradianceCube(std::vector<float>(texels.begin(), texels.end()), sourceSize, size);
        std::vector<double> flat;
        for (const auto& value : rgb) flat.insert(flat.end(), {value.r, value.g, value.b});
        return flat;
    });
    bake::IrradianceKernels steps(context);
    std::optional<bake::Irradiance> irradiance;
    const auto timing = timeRepeated(options.repeat, [&] {
        bake::BakeProgress progress(true);
        irradiance.emplace(bake::computeIrradiance(context, steps, source, size, progress));
        return progress.steps().back().deviceMilliseconds;
    });
    const auto values = irradiance->cube.download(context);
    double sumSquares = 0, worst = 0;
    const size_t count = reference.size() / 3;
    for (size_t i = 0; i < count; ++i) {
        const double error = relativeLuminanceError({values[4 * i], values[4 * i + 1], values[4 * i + 2]},
                                                    {reference[3 * i], reference[3 * i + 1], reference[3 * i + 2]});
        sumSquares += error * error;
        worst = std::max(worst, std::isnan(error) ? INFINITY : error);
    }
    return {BenchOutput::Irradiance, {}, "exact-sum", 0, 0, timing.deviceMilliseconds, timing.wallMilliseconds,
            options.repeat, std::sqrt(sumSquares / double(count)), worst, {}};
}

} // namespace iblkit::bench
