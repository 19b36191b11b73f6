#pragma once

#include "bake_progress.hpp"
#include "environment_input.hpp"
#include "buffer.hpp"
#include "image.hpp"
#include "kernels/kernel_parameters.hpp"
#include "kernels/kernel.hpp"
#include "kernels/kernel_table.hpp"
#include "kernels/lut_methods.hpp"
#include "kernels/specular_method.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::bake {

// The environment as an RGBA32F cube of `size` with its full mip chain (2x2 means).
vulkan::Image buildSourceCube(const vulkan::VulkanContext& context, const EnvironmentInput& input, uint32_t size,
                              BakeProgress& progress);

// The levels of a shading recipe: mip m at roughness[m] where prefiltered[m] (every mip when it
// is empty), from `source` below residualFrom and from `residual` (the environment with its
// lights taken out) from there on; mip 0, and every mip not prefiltered, is its source's own.
struct SpecularLevels {
    std::vector<float> roughness;
    std::vector<bool> prefiltered;
    vulkan::Image* residual = nullptr;
    uint32_t residualFrom = 0;
};
vulkan::Image prefilterLevels(const vulkan::VulkanContext& context, vulkan::Image& source, const SpecularLevels& levels,
                              kernels::SpecularMethod* prefilter, BakeProgress& progress);

// A 1x1 LUT of zeros, for the preview of a bake that needs no LUT.
vulkan::Image blankBrdfLut(const vulkan::VulkanContext& context);

// The LUT over size x size by `integrator`, stored as R32G32_SFLOAT (the host rounds to 16 bits).
vulkan::Image integrateBrdfLut(const vulkan::VulkanContext& context, uint32_t size, kernels::LutMethod& integrator,
                               BakeProgress& progress);

struct IrradianceSh {
    std::array<glm::dvec3, 9> shRadiance{}; // projections of radiance on Y_lm (Common/SphericalHarmonics.fxh)
    double solidAngle = 0;                  // the sphere's 4 pi as the projection's texels summed it
    uint32_t shSourceSize = 0;              // the source mip each was computed from
    uint32_t cubeSourceSize = 0;
};

struct Irradiance {
    vulkan::Image cube; // RGBA32F, E(n) / pi
    IrradianceSh sh;
};

// The kit's kernel for `role` (a role with one kernel), compiled from the built-in hlsl/.
kernels::Kernel makeKernel(const vulkan::VulkanContext& context, kernels::KernelRole role);

// The first mip of a `size` chain whose faces are at most `limit` across.
uint32_t firstMipAtMost(uint32_t size, uint32_t limit);

// The source mip at most this size that the irradiance steps read.
inline constexpr uint32_t kShSourceLimit = 64;
inline constexpr uint32_t kIrradianceSourceLimit = 32;
// The irradiance cube's moments are summed from the mip at most this many times finer, and its
// moment cube is at most this size (IrradianceCubeCS's loop: 6 x 64² iterations within llvmpipe's
// 65535 for the invocation).
inline constexpr uint32_t kMomentRatio = 8;
inline constexpr uint32_t kMaxMomentSize = 64;

// The two kernels of the irradiance step, compiled once for repeated runs or ahead of the step.
struct IrradianceKernels {
    explicit IrradianceKernels(const vulkan::VulkanContext& context);
    kernels::Kernel project, cube;
};

// The cube the irradiance is summed from, with its mip 0's texels where the host holds them
// already (takeOutLights' restMipZero); else the step reads back the mip it needs.
struct IrradianceSource {
    IrradianceSource(vulkan::Image& cube, std::span<const float> mipZero = {}) : cube(cube), mipZero(mipZero) {}
    vulkan::Image& cube;
    std::span<const float> mipZero;
};

// The SH projection always (the manifest's coefficients and the preview's exposure); the cube
// only `withCube`, else it is zeros. The cube sums the radiance moments of the mip at most
// cubeSourceLimit across, each taken from the mip kMomentRatio times finer.
Irradiance computeIrradiance(const vulkan::VulkanContext& context, IrradianceKernels& steps, const IrradianceSource& source,
                             uint32_t size, BakeProgress& progress, bool withCube = true,
                             uint32_t cubeSourceLimit = kIrradianceSourceLimit);

struct Preview {
    uint32_t width, height;
    std::vector<float> rgba; // tone mapped, sRGB encoded, in [0, 1]
};

inline constexpr uint32_t kPreviewColumns = 7;   // roughness 0, 1/6, ..., 1
inline constexpr uint32_t kPreviewRows = 3;      // metalness 0, 0.5, 1
inline constexpr uint32_t kPreviewCellSize = 128;

// What the preview shades with: the maps, the lights and the recipe that reads them.
struct PreviewMaps {
    vulkan::Image& specular;
    vulkan::Image& irradiance;
    vulkan::Image& brdfLut;
    vulkan::Image& lobeTable;
    const vulkan::Buffer& lights;
    kernels::IblRecipeParameters recipe;
};

// `kernel`: PreviewCS (kernels::KernelRole::Preview).
Preview renderPreview(const vulkan::VulkanContext& context, kernels::Kernel& kernel, const PreviewMaps& maps, float exposure,
                      BakeProgress& progress);

} // namespace iblkit::bake
