#include "kernels/kernel_steps.hpp"

#include "buffer.hpp"

#include <algorithm>
#include <numbers>
#include <vector>

namespace iblkit::kernels {

void runSkyCube(Kernel& kernel, vulkan::Image& cube, const SupersampleParameters& parameters) {
    kernel.program().bind("Cube", cube, 0);
    kernel.setParameters(parameters.members());
    kernel.run({cube.desc().width, cube.desc().width, 6});
}

void runEquirectToCube(Kernel& kernel, vulkan::Image& equirect, vulkan::Image& cube, const SupersampleParameters& parameters) {
    kernel.program().bind("Equirect", equirect);
    kernel.program().bind("Cube", cube, 0);
    kernel.setParameters(parameters.members());
    kernel.run({cube.desc().width, cube.desc().width, 6});
}

void runDownsampleChain(Kernel& kernel, vulkan::Image& cube) {
    kernel.program().bind("Source", cube);
    for (uint32_t mip = 1; mip < cube.desc().mips; ++mip) {
        kernel.program().bind("Destination", cube, mip);
        kernel.setParameters(SourceMipParameters{mip - 1}.members());
        kernel.run({cube.mipWidth(mip), cube.mipWidth(mip), 6});
    }
}

namespace {

// The prefilters that read EnvMap through EnvMapSampler into one mip of Prefiltered, a thread a
// texel, with nothing else bound.
void runEnvMapPrefilter(Kernel& kernel, vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target,
                        uint32_t mip, const NamedValues& parameters) {
    kernel.program().bind("EnvMap", source);
    kernel.program().bind("EnvMapSampler", sampler);
    kernel.program().bind("Prefiltered", target, mip);
    kernel.setParameters(parameters);
    kernel.run({target.mipWidth(mip), target.mipWidth(mip), 6});
}

} // namespace

void runPrefilter(Kernel& kernel, vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target,
                  uint32_t mip, const PrefilterParameters& parameters) {
    runEnvMapPrefilter(kernel, source, sampler, target, mip, parameters.members());
}

void runPrefilterChunk(Kernel& kernel, vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& accumulator,
                       vulkan::Image& target, uint32_t mip, const PrefilterChunkParameters& parameters) {
    kernel.program().bind("EnvMap", source);
    kernel.program().bind("EnvMapSampler", sampler);
    kernel.program().bind("Accumulated", accumulator);
    kernel.program().bind("Prefiltered", target, mip);
    kernel.setParameters(parameters.members());
    kernel.run({target.mipWidth(mip), target.mipWidth(mip), 6});
}

void runPrefilterChunked(Kernel& kernel, vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target,
                         uint32_t mip, float roughness, uint32_t samples, uint32_t chunk) {
    const uint32_t size = target.mipWidth(mip);
    vulkan::Image accumulator(kernel.context(),
                              {"Accumulated", &vulkan::texelFormatNamed("R32G32B32A32_SFLOAT"), size, size, 6, 1, false, true});
    forEachChunk(samples, chunk, [&](uint32_t first, uint32_t count, bool last) {
        runPrefilterChunk(kernel, source, sampler, accumulator, target, mip, {roughness, first, count, last});
    });
}

void runPrefilterTable(Kernel& kernel, vulkan::Image& source, const vulkan::Sampler& sampler, const vulkan::Buffer& table,
                       uint32_t entries, vulkan::Image& target, uint32_t mip) {
    kernel.program().bind("EnvMap", source);
    kernel.program().bind("EnvMapSampler", sampler);
    kernel.program().bind("SampleTable", table);
    kernel.program().bind("Prefiltered", target, mip);
    kernel.setParameters(PrefilterTableParameters{entries}.members());
    kernel.run({target.mipWidth(mip), target.mipWidth(mip), 6});
}

void runPrefilterPyramid(Kernel& kernel, vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target,
                         uint32_t mip, const PrefilterPyramidParameters& reads) {
    runEnvMapPrefilter(kernel, source, sampler, target, mip, reads.members());
}

void runPrefilterRing(Kernel& kernel, vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target,
                      uint32_t mip, const PrefilterRingParameters& ring) {
    runEnvMapPrefilter(kernel, source, sampler, target, mip, ring.members());
}

void runClusterPyramid(Kernel& kernel, vulkan::Image& source, const EnergyPyramid& pyramid) {
    kernel.program().bind("Source", source);
    kernel.program().bind("EnergyIn", pyramid.energy);
    kernel.program().bind("CentroidIn", pyramid.centroid);
    kernel.program().bind("GeometryIn", pyramid.geometry);
    if (!pyramid.holdsSourceTexels && source.desc().width < 2) { // no block of more than one texel: the one texel is a face
        pyramid.texelSolidAngle.upload(kernel.context(), std::vector<float>{float(4 * std::numbers::pi / 6)});
        return;
    }
    kernel.program().bind("TexelSolidAngle", pyramid.texelSolidAngle, 0);
    for (uint32_t level = 0; level < pyramid.energy.desc().mips; ++level) {
        kernel.program().bind("Energy", pyramid.energy, level);
        kernel.program().bind("Centroid", pyramid.centroid, level);
        kernel.program().bind("Geometry", pyramid.geometry, level);
        kernel.setParameters(ClusterParameters{level}.members());
        const uint32_t size = pyramid.energy.mipWidth(level);
        kernel.run({size, size, 6});
    }
}

uint32_t pyramidSize(uint32_t sourceSize) { return std::max(sourceSize / 2, 1u); }

void runPrefilterConvolution(Kernel& kernel, vulkan::Image& source, const EnergyPyramid& pyramid, vulkan::Image& target,
                             uint32_t mip, const PrefilterConvolutionParameters& parameters) {
    if (!pyramid.holdsSourceTexels) {
        kernel.program().bind("Source", source);
        kernel.program().bind("TexelSolidAngle", pyramid.texelSolidAngle);
    }
    kernel.program().bind("Energy", pyramid.energy);
    kernel.program().bind("Centroid", pyramid.centroid);
    kernel.program().bind("Geometry", pyramid.geometry);
    kernel.program().bind("Prefiltered", target, mip);
    kernel.setParameters(parameters.members());
    kernel.run({target.mipWidth(mip), target.mipWidth(mip), 6});
}

void runBrdfLut(Kernel& kernel, vulkan::Image& lut) {
    kernel.program().bind("Precomputed", lut);
    kernel.run({lut.desc().width, lut.desc().height, 1});
}

void runBrdfLutChunk(Kernel& kernel, vulkan::Image& accumulator, vulkan::Image& lut, const BrdfChunkParameters& parameters) {
    kernel.program().bind("Accumulated", accumulator);
    kernel.program().bind("Precomputed", lut);
    kernel.setParameters(parameters.members());
    kernel.run({lut.desc().width, lut.desc().height, 1});
}

void runBrdfLutChunked(Kernel& kernel, vulkan::Image& lut, uint32_t samples, uint32_t chunk) {
    const auto& desc = lut.desc();
    vulkan::Image accumulator(kernel.context(), {"Accumulated", &vulkan::texelFormatNamed("R32G32_SFLOAT"), desc.width,
                                                 desc.height, 1, 1, false, true});
    forEachChunk(samples, chunk, [&](uint32_t first, uint32_t count, bool last) {
        runBrdfLutChunk(kernel, accumulator, lut, {first, count, last});
    });
}

void runBrdfLutGrid(Kernel& kernel, const vulkan::Buffer& grid, uint32_t gridSize) {
    kernel.program().bind("Grid", grid);
    kernel.setParameters(LutGridParameters{gridSize}.members());
    kernel.run({gridSize, gridSize, 1});
}

void runBrdfLutResample(Kernel& kernel, const vulkan::Buffer& grid, uint32_t gridSize, vulkan::Image& lut) {
    kernel.program().bind("Grid", grid);
    kernel.program().bind("Precomputed", lut);
    kernel.setParameters(LutGridParameters{gridSize}.members());
    kernel.run({lut.desc().width, lut.desc().height, 1});
}

ShProjection runShProject(const vulkan::VulkanContext& context, Kernel& kernel, vulkan::Image& source, uint32_t mip) {
    const uint32_t size = source.mipWidth(mip), groupsPerSide = (size + 7) / 8;
    const uint32_t groups = groupsPerSide * groupsPerSide * 6;
    vulkan::Buffer partials(context, vk::DeviceSize(groups) * 9 * 16, vk::BufferUsageFlagBits::eStorageBuffer, "Partials");
    kernel.program().bind("Source", source);
    kernel.program().bind("Partials", partials);
    kernel.setParameters(SourceMipParameters{mip}.members());
    kernel.runGroups({groupsPerSide, groupsPerSide, 6});
    const auto bytes = partials.read();
    return sumShPartials({reinterpret_cast<const float*>(bytes.data()), bytes.size() / sizeof(float)}, groups);
}

ShProjection sumShPartials(std::span<const float> partials, uint32_t groups) {
    ShProjection projection{};
    for (uint32_t group = 0; group < groups; ++group)
        for (uint32_t k = 0; k < 9; ++k) {
            const float* at = &partials[(size_t(group) * 9 + k) * 4];
            projection.radiance[k] += glm::dvec3(at[0], at[1], at[2]);
            if (k == 0) projection.solidAngle += at[3];
        }
    return projection;
}

void runIrradianceCube(Kernel& kernel, const vulkan::Buffer& moments, uint32_t momentSize, vulkan::Image& target) {
    kernel.program().bind("Moments", moments);
    kernel.program().bind("Irradiance", target, 0);
    kernel.setParameters(IrradianceParameters{momentSize}.members());
    kernel.run({target.desc().width, target.desc().width, 6});
}

void runPreview(Kernel& kernel, const PreviewResources& resources, const PreviewParameters& parameters) {
    auto& program = kernel.program();
    program.bind("Specular", resources.specular);
    program.bind("IrradianceMap", resources.irradiance);
    program.bind("BrdfLut", resources.brdfLut);
    program.bind("LobeTable", resources.lobeTable);
    program.bind("Lights", resources.lights);
    program.bind("LinearClamp", resources.sampler);
    program.bind("Preview", resources.image);
    kernel.setParameters(parameters.members());
    kernel.run({resources.image.desc().width, resources.image.desc().height, 1});
}

void runRenderReference(Kernel& kernel, const RenderReferenceResources& resources, const RenderReferenceParameters& parameters) {
    auto& program = kernel.program();
    program.bind("Spheres", resources.spheres);
    program.bind("Environment", resources.environment);
    program.bind("EnvironmentCdf", resources.environmentCdf);
    program.bind("Lights", resources.lights);
    program.bind("ActivePixels", resources.activePixels);
    program.bind("RadianceSum", resources.radianceSum);
    program.bind("SquareSum", resources.squareSum);
    kernel.setParameters(parameters.members());
    kernel.run({parameters.activeCount, 1, 1});
}

void runRenderSplitSum(Kernel& kernel, const RenderSplitSumResources& resources, const RenderSplitSumParameters& parameters) {
    auto& program = kernel.program();
    program.bind("Spheres", resources.spheres);
    program.bind("Specular", resources.specular);
    program.bind("IrradianceMap", resources.irradiance);
    program.bind("BrdfLut", resources.brdfLut);
    program.bind("LobeTable", resources.lobeTable);
    program.bind("TransmissionTable", resources.transmissionTable);
    program.bind("SphereTransmissionTable", resources.sphereTransmissionTable);
    program.bind("Lights", resources.lights);
    program.bind("LinearClamp", resources.sampler);
    program.bind("SplitSum", resources.image);
    kernel.setParameters(parameters.members());
    kernel.run({resources.image.desc().width, resources.image.desc().height, 1});
}

void runProbe(Kernel& kernel, const ProbeBuffers& buffers, uint32_t argumentCount) {
    kernel.program().bind("Arguments", buffers.arguments);
    if (buffers.sampleIndices) kernel.program().bind("SampleIndices", *buffers.sampleIndices);
    kernel.program().bind("Results", buffers.results);
    kernel.setParameters(ProbeParameters{argumentCount}.members());
    kernel.run({argumentCount, 1, 1});
}

} // namespace iblkit::kernels
