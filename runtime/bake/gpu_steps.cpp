#include "gpu_steps.hpp"

#include "kernels/specular_method.hpp"

#include "kernels/kernel_steps.hpp"
#include "kernels/sampled_methods.hpp"
#include "bake_settings.hpp"
#include "buffer.hpp"
#include "image_transfer.hpp"
#include "reference_irradiance.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace iblkit::bake {
namespace {

using kernels::Kernel;
using kernels::KernelRole;


vulkan::Image makeCube(const vulkan::VulkanContext& context, const std::string& name, uint32_t size, uint32_t mips) {
    return vulkan::Image(context, {name, &vulkan::rgba32Float(), size, size, 6, mips, true, true});
}

// The kernel's device time so far goes to the progress step.
void report(Kernel& kernel, BakeProgress& progress) { progress.addDeviceTime(kernel.takeTotals().deviceMilliseconds); }

// Cube texels spanning more than one panorama texel average several reads (see EquirectToCubeCS).
uint32_t supersampleFor(uint32_t panoramaWidth, uint32_t size) {
    return std::clamp<uint32_t>((panoramaWidth + 4 * size - 1) / (4 * size), 1, 16);
}

void renderSky(const vulkan::VulkanContext& context, vulkan::Image& cube, BakeProgress& progress) {
    auto kernel = makeKernel(context, KernelRole::SkyCube);
    kernels::runSkyCube(kernel, cube, {kSkySupersample});
    report(kernel, progress);
}

void convertPanorama(const vulkan::VulkanContext& context, const image_io::FloatImage& panorama, vulkan::Image& cube,
                     BakeProgress& progress) {
    progress.part("panorama upload");
    vulkan::Image equirect(context, {"Equirect", &vulkan::rgba32Float(), panorama.width, panorama.height, 1, 1, false, false});
    equirect.upload(context, image_io::rgbaValues(panorama));
    progress.part("panorama kernel");
    auto kernel = makeKernel(context, KernelRole::EquirectToCube);
    progress.part("panorama to mip 0");
    kernels::runEquirectToCube(kernel, equirect, cube, {supersampleFor(panorama.width, cube.desc().width)});
    report(kernel, progress);
}

void uploadFaces(const vulkan::VulkanContext& context, const std::vector<float>& mip0, vulkan::Image& cube) {
    std::vector<float> values(cube.valueCount(), 0.f);
    std::copy(mip0.begin(), mip0.end(), values.begin());
    cube.upload(context, values);
}

} // namespace

Kernel makeKernel(const vulkan::VulkanContext& context, KernelRole role) {
    return Kernel(context, kernels::compileKernel(kernels::kernelFor(role)));
}

uint32_t firstMipAtMost(uint32_t size, uint32_t limit) {
    uint32_t mip = 0;
    while ((size >> mip) > limit) ++mip;
    return mip;
}

vulkan::Image buildSourceCube(const vulkan::VulkanContext& context, const EnvironmentInput& input, uint32_t size,
                              BakeProgress& progress) {
    progress.begin("source cube");
    progress.part("allocation");
    auto cube = makeCube(context, "Source", size, vulkan::fullMipCount(size, size));
    if (input.kind == InputKind::BuiltIn) {
        progress.part("sky to mip 0");
        renderSky(context, cube, progress);
    } else if (input.kind == InputKind::Panorama) {
        convertPanorama(context, input.panorama, cube, progress);
    } else {
        progress.part("mip 0 upload");
        uploadFaces(context, input.cubeTexels, cube);
    }
    progress.advance(0.5, "mip chain");
    progress.part("mip chain");
    auto downsample = makeKernel(context, KernelRole::DownsampleCube);
    kernels::runDownsampleChain(downsample, cube);
    report(downsample, progress);
    progress.end();
    return cube;
}

vulkan::Image prefilterLevels(const vulkan::VulkanContext& context, vulkan::Image& source, const SpecularLevels& levels,
                              kernels::SpecularMethod* prefilter, BakeProgress& progress) {
    progress.begin("prefilter");
    const uint32_t size = source.desc().width, mips = uint32_t(levels.roughness.size());
    auto specular = makeCube(context, "Specular", size, mips);
    const auto sourceOf = [&](uint32_t mip) -> vulkan::Image& {
        return levels.residual && mip >= levels.residualFrom ? *levels.residual : source;
    };
    specular.copyMipFrom(context, sourceOf(0), 0);
    const vulkan::Sampler linear(context, {});
    const auto convolved = [&](uint32_t mip) { return prefilter && (levels.prefiltered.empty() || levels.prefiltered[mip]); };
    double work = 0, done = 0; // texels still to convolve, for the percentage
    for (uint32_t mip = 1; mip < mips; ++mip)
        if (convolved(mip)) work += std::pow(double(specular.mipWidth(mip)), 2);
    for (uint32_t mip = 1; mip < mips; ++mip) {
        if (!convolved(mip)) {
            specular.copyMipFrom(context, sourceOf(mip), mip);
            continue;
        }
        progress.advance(done / work, fmt::format("mip {} of {}", mip, mips - 1));
        progress.part(fmt::format("mip {}", mip));
        prefilter->run(sourceOf(mip), linear, specular, mip, levels.roughness[mip]);
        progress.addDeviceTime(prefilter->takeTotals().deviceMilliseconds);
        done += std::pow(double(specular.mipWidth(mip)), 2);
    }
    if (prefilter) prefilter->releaseSourceData(); // the download and the preview that follow need the room
    progress.end();
    return specular;
}

vulkan::Image blankBrdfLut(const vulkan::VulkanContext& context) {
    vulkan::Image lut(context, {"BrdfLut", &vulkan::texelFormatNamed("R32G32_SFLOAT"), 1, 1, 1, 1, false, true});
    lut.upload(context, std::vector<float>(2, 0.f));
    return lut;
}

vulkan::Image integrateBrdfLut(const vulkan::VulkanContext& context, uint32_t size, kernels::LutMethod& integrator,
                               BakeProgress& progress) {
    progress.begin("brdf lut");
    vulkan::Image lut(context, {"BrdfLut", &vulkan::texelFormatNamed("R32G32_SFLOAT"), size, size, 1, 1, false, true});
    integrator.run(lut);
    progress.addDeviceTime(integrator.takeTotals().deviceMilliseconds);
    progress.end();
    return lut;
}

IrradianceKernels::IrradianceKernels(const vulkan::VulkanContext& context)
    : project(makeKernel(context, KernelRole::ShProject)), cube(makeKernel(context, KernelRole::IrradianceCube)) {}

Irradiance computeIrradiance(const vulkan::VulkanContext& context, IrradianceKernels& steps, const IrradianceSource& from,
                             uint32_t size, BakeProgress& progress, bool withCube, uint32_t cubeSourceLimit) {
    auto& source = from.cube;
    progress.begin("irradiance");
    Irradiance result{makeCube(context, "Irradiance", size, 1), {}};
    progress.part("sh");
    const uint32_t shMip = firstMipAtMost(source.desc().width, kShSourceLimit);
    const auto projection = kernels::runShProject(context, steps.project, source, shMip);
    report(steps.project, progress);
    result.sh.shRadiance = projection.radiance;
    result.sh.solidAngle = projection.solidAngle;
    result.sh.shSourceSize = source.mipWidth(shMip);
    const uint32_t mip = firstMipAtMost(source.desc().width, cubeSourceLimit);
    result.sh.cubeSourceSize = source.mipWidth(mip);
    if (!withCube) {
        result.cube.upload(context, std::vector<float>(result.cube.valueCount(), 0.f));
        progress.end();
        return result;
    }
    progress.advance(0.1, "cube");
    progress.part("moments");
    const uint32_t momentSize = source.mipWidth(mip);
    if (momentSize > kMaxMomentSize)
        throw std::invalid_argument(fmt::format("irradiance source of {}² is past the most the irradiance cube sums, {}²",
                                                momentSize, kMaxMomentSize));
    const uint32_t fineMip = firstMipAtMost(source.desc().width, momentSize * kMomentRatio);
    std::vector<float> downloaded;
    std::span<const float> fine = from.mipZero;
    if (fineMip != 0 || fine.empty()) fine = downloaded = vulkan::downloadMip(context, source, fineMip);
    const auto moments = reference::irradianceMoments(fine, source.mipWidth(fineMip), momentSize);
    progress.part("cube");
    const auto momentBuffer = vulkan::storageBuffer(context, std::as_bytes(std::span(moments)), "Moments");
    kernels::runIrradianceCube(steps.cube, momentBuffer, momentSize, result.cube);
    report(steps.cube, progress);
    progress.end();
    return result;
}

Preview renderPreview(const vulkan::VulkanContext& context, kernels::Kernel& kernel, const PreviewMaps& maps, float exposure,
                      BakeProgress& progress) {
    progress.begin("preview");
    const uint32_t width = kPreviewColumns * kPreviewCellSize, mips = maps.specular.desc().mips;
    const uint32_t panelWidth = width / mips, height = kPreviewRows * kPreviewCellSize + panelWidth / 2;
    vulkan::Image image(context, {"Preview", &vulkan::rgba32Float(), width, height, 1, 1, false, true});
    const vulkan::Sampler linear(context, {});
    kernels::runPreview(kernel, {maps.specular, maps.irradiance, maps.brdfLut, maps.lobeTable, maps.lights, linear, image},
                        {kPreviewColumns, kPreviewRows, kPreviewCellSize, mips, panelWidth, exposure, maps.recipe});
    report(kernel, progress);
    Preview preview{width, height, image.download(context)};
    progress.end();
    return preview;
}

} // namespace iblkit::bake
