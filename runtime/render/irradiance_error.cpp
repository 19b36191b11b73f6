#include "render/irradiance_error.hpp"

#include "image_transfer.hpp"
#include "measurements.hpp"
#include "shading_maps.hpp"
#include "reference_cache.hpp"
#include "reference_irradiance.hpp"
#include "shading/disk_light.hpp"

#include <fmt/core.h>

namespace iblkit::render {

std::vector<glm::dvec3> exactIrradiance(const vulkan::VulkanContext& context, const vulkan::Image& source, uint32_t size,
                                        const std::filesystem::path& cache) {
    const uint32_t sourceSize = source.desc().width;
    const auto texels = vulkan::downloadMip(context, source, 0);
    const auto key = bench::ReferenceCache::key(fmt::format("exact irradiance v2 (Lambert's clipped texels) source {} output {}", sourceSize, size),
                                                std::as_bytes(std::span(texels)));
    return bench::unflatten(bench::ReferenceCache(cache).getOrCompute(key, size_t(6) * size * size * 3, [&] {
        return bench::flatten(reference::exactIrradianceCube(texels, sourceSize, size));
    }));
}

IrradianceError irradianceError(const std::vector<glm::dvec3>& exact, const std::vector<float>& irradianceCube, uint32_t size,
                                const std::vector<shading::EnvironmentLight>& lights) {
    bench::ErrorSummary errors;
    size_t texel = 0;
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t row = 0; row < size; ++row)
            for (uint32_t column = 0; column < size; ++column, ++texel) {
                glm::dvec3 read(irradianceCube[4 * texel], irradianceCube[4 * texel + 1], irradianceCube[4 * texel + 2]);
                const glm::dvec3 normal = reference::cubeTexelCentre(face, column, row, size);
                for (const auto& light : lights) read += shading::diskIrradianceOverPi(light, normal);
                errors.add(bench::relativeLuminanceError(read, exact[texel]));
            }
    return {errors.rms(), errors.max()};
}

} // namespace iblkit::render
