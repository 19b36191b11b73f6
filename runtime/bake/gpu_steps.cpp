#include "gpu_steps.hpp"

#include "bake_kernel.hpp"
#include "bake_settings.hpp"
#include "buffer.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace iblkit::bake {
namespace {

const vulkan::TexelFormat& rgba32() { return vulkan::texelFormatNamed("R32G32B32A32_SFLOAT"); }

vulkan::Image makeCube(const vulkan::VulkanContext& context, const std::string& name, uint32_t size, uint32_t mips) {
    return vulkan::Image(context, {name, &rgba32(), size, size, 6, mips, true, true});
}

uint32_t firstMipAtMost(uint32_t size, uint32_t limit) {
    uint32_t mip = 0;
    while ((size >> mip) > limit) ++mip;
    return mip;
}

// Cube texels spanning more than one panorama texel average several reads (see EquirectToCubeCS).
uint32_t supersampleFor(uint32_t panoramaWidth, uint32_t size) {
    return std::clamp<uint32_t>((panoramaWidth + 4 * size - 1) / (4 * size), 1, 16);
}

void convertPanorama(const vulkan::VulkanContext& context, const image_io::FloatImage& panorama, vulkan::Image& cube,
                     BakeProgress& progress) {
    vulkan::Image equirect(context, {"Equirect", &rgba32(), panorama.width, panorama.height, 1, 1, false, false});
    equirect.upload(context, image_io::rgbaValues(panorama));
    BakeKernel kernel(context, compileBakeShader("EquirectToCubeCS"));
    kernel.program().bind("Equirect", equirect);
    kernel.program().bind("Cube", cube, 0);
    kernel.setParameters({{"Supersample", {double(supersampleFor(panorama.width, cube.desc().width))}}});
    kernel.run({cube.desc().width, cube.desc().width, 6}, progress);
}

void uploadFaces(const vulkan::VulkanContext& context, const std::vector<float>& mip0, vulkan::Image& cube) {
    std::vector<float> values(cube.valueCount(), 0.f);
    std::copy(mip0.begin(), mip0.end(), values.begin());
    cube.upload(context, values);
}

void downsampleChain(const vulkan::VulkanContext& context, vulkan::Image& cube, BakeProgress& progress) {
    BakeKernel kernel(context, compileBakeShader("DownsampleCubeCS"));
    kernel.program().bind("Source", cube);
    for (uint32_t mip = 1; mip < cube.desc().mips; ++mip) {
        kernel.program().bind("Destination", cube, mip);
        kernel.setParameters({{"SourceMip", {double(mip - 1)}}});
        kernel.run({cube.mipWidth(mip), cube.mipWidth(mip), 6}, progress);
    }
}

} // namespace

vulkan::Image buildSourceCube(const vulkan::VulkanContext& context, const EnvironmentInput& input, uint32_t size,
                              BakeProgress& progress) {
    progress.begin("source cube");
    auto cube = makeCube(context, "Source", size, vulkan::fullMipCount(size, size));
    if (input.kind == InputKind::BuiltIn || input.kind == InputKind::Panorama)
        convertPanorama(context, input.panorama, cube, progress);
    else
        uploadFaces(context, input.cubeTexels, cube);
    progress.advance(0.5, "mip chain");
    downsampleChain(context, cube, progress);
    progress.end();
    return cube;
}

vulkan::Image prefilterSpecular(const vulkan::VulkanContext& context, vulkan::Image& source, uint32_t mips,
                                uint32_t samples, BakeProgress& progress) {
    progress.begin("prefilter");
    const uint32_t size = source.desc().width;
    auto specular = makeCube(context, "Specular", size, mips);
    specular.copyMipFrom(context, source, 0);
    BakeKernel kernel(context, compileBakeShader("PrefilterSpecularCS", {{"SAMPLE_COUNT", std::to_string(samples)}}));
    const vulkan::Sampler linear(context, {});
    kernel.program().bind("EnvMap", source);
    kernel.program().bind("EnvMapSampler", linear);
    double work = 0, done = 0; // texels still to convolve, for the percentage
    for (uint32_t mip = 1; mip < mips; ++mip) work += std::pow(double(specular.mipWidth(mip)), 2);
    for (uint32_t mip = 1; mip < mips; ++mip) {
        progress.advance(done / work, fmt::format("mip {} of {}", mip, mips - 1));
        kernel.program().bind("Prefiltered", specular, mip);
        kernel.setParameters({{"Roughness", {roughnessOfMip(mip, mips)}}});
        kernel.run({specular.mipWidth(mip), specular.mipWidth(mip), 6}, progress);
        done += std::pow(double(specular.mipWidth(mip)), 2);
    }
    progress.end();
    return specular;
}

vulkan::Image integrateBrdfLut(const vulkan::VulkanContext& context, uint32_t size, uint32_t samples,
                               BakeProgress& progress) {
    progress.begin("brdf lut");
    BakeKernel kernel(context, compileBakeShader("PrecomputedBrdfCS", {{"SAMPLE_COUNT", std::to_string(samples)}},
                                                 {{"Precomputed", "rg32f"}}));
    vulkan::Image lut(context, {"BrdfLut", &vulkan::texelFormatNamed("R32G32_SFLOAT"), size, size, 1, 1, false, true});
    kernel.program().bind("Precomputed", lut);
    kernel.run({size, size, 1}, progress);
    progress.end();
    return lut;
}

namespace {

void projectSh(const vulkan::VulkanContext& context, vulkan::Image& source, Irradiance& result, BakeProgress& progress) {
    const uint32_t mip = firstMipAtMost(source.desc().width, kShSourceLimit);
    const uint32_t size = source.mipWidth(mip), groupsPerSide = (size + 7) / 8;
    const uint32_t groups = groupsPerSide * groupsPerSide * 6;
    vulkan::Buffer partials(context, vk::DeviceSize(groups) * 9 * 16, vk::BufferUsageFlagBits::eStorageBuffer, "Partials");
    BakeKernel kernel(context, compileBakeShader("ShProjectCS"));
    kernel.program().bind("Source", source);
    kernel.program().bind("Partials", partials);
    kernel.setParameters({{"SourceMip", {double(mip)}}});
    kernel.runGroups({groupsPerSide, groupsPerSide, 6}, progress);
    const auto bytes = partials.read();
    const auto* values = reinterpret_cast<const float*>(bytes.data());
    result.shRadiance.fill(glm::dvec3(0));
    result.solidAngle = 0;
    for (uint32_t group = 0; group < groups; ++group)
        for (uint32_t k = 0; k < 9; ++k) {
            const float* at = values + (size_t(group) * 9 + k) * 4;
            result.shRadiance[k] += glm::dvec3(at[0], at[1], at[2]);
            if (k == 0) result.solidAngle += at[3];
        }
    result.shSourceSize = size;
}

} // namespace

Irradiance computeIrradiance(const vulkan::VulkanContext& context, vulkan::Image& source, uint32_t size,
                             BakeProgress& progress) {
    progress.begin("irradiance");
    Irradiance result{makeCube(context, "Irradiance", size, 1), {}, 0, 0, 0};
    projectSh(context, source, result, progress);
    progress.advance(0.1, "cube");
    const uint32_t mip = firstMipAtMost(source.desc().width, kIrradianceSourceLimit);
    BakeKernel kernel(context, compileBakeShader("IrradianceCubeCS"));
    kernel.program().bind("Source", source);
    kernel.program().bind("Irradiance", result.cube, 0);
    kernel.setParameters({{"SourceMip", {double(mip)}}});
    kernel.run({size, size, 6}, progress);
    result.cubeSourceSize = source.mipWidth(mip);
    progress.end();
    return result;
}

Preview renderPreview(const vulkan::VulkanContext& context, vulkan::Image& specular, vulkan::Image& irradiance,
                      vulkan::Image& brdfLut, float exposure, BakeProgress& progress) {
    progress.begin("preview");
    const uint32_t width = kPreviewColumns * kPreviewCellSize, mips = specular.desc().mips;
    const uint32_t panelWidth = width / mips, height = kPreviewRows * kPreviewCellSize + panelWidth / 2;
    vulkan::Image image(context, {"Preview", &rgba32(), width, height, 1, 1, false, true});
    const vulkan::Sampler linear(context, {});
    BakeKernel kernel(context, compileBakeShader("PreviewCS"));
    kernel.program().bind("Specular", specular);
    kernel.program().bind("IrradianceMap", irradiance);
    kernel.program().bind("BrdfLut", brdfLut);
    kernel.program().bind("LinearClamp", linear);
    kernel.program().bind("Preview", image);
    kernel.setParameters({{"Columns", {double(kPreviewColumns)}},
                          {"Rows", {double(kPreviewRows)}},
                          {"CellSize", {double(kPreviewCellSize)}},
                          {"SpecularMips", {double(mips)}},
                          {"StripPanelWidth", {double(panelWidth)}},
                          {"Exposure", {exposure}}});
    kernel.run({width, height, 1}, progress);
    Preview preview{width, height, image.download(context)};
    progress.end();
    return preview;
}

} // namespace iblkit::bake
