#pragma once

#include "image.hpp"
#include "shading/light_extraction.hpp"
#include "context_options.hpp"

#include <glm/vec3.hpp>

#include <filesystem>
#include <vector>

namespace iblkit::render {

// The exact E(n) / π of an environment at the texel centres of a size² cube: the integral over
// the source cube's mip 0, its texels constant (reference::exactIrradianceCube: Lambert's formula
// where a normal's horizon cuts a texel, where a sum of texel centres errs by over 1 % beside a
// low sun), kept in the reference cache.
std::vector<glm::dvec3> exactIrradiance(const vulkan::VulkanContext& context, const vulkan::Image& source, uint32_t size,
                                        const std::filesystem::path& cache);

// What a recipe's diffuse reads against the exact sum, in relative error of luminance over every
// texel: the irradiance map's texel (RGBA32F, E / π of what the maps hold) plus each light's
// E / π as IblDiskLight adds it.
struct IrradianceError {
    double rms = 0, max = 0;
};
IrradianceError irradianceError(const std::vector<glm::dvec3>& exact, const std::vector<float>& irradianceCube, uint32_t size,
                                const std::vector<shading::EnvironmentLight>& lights);

} // namespace iblkit::render
