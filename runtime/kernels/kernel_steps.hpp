#pragma once

#include "kernels/kernel.hpp"

#include "buffer.hpp"
#include "image.hpp"

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>

namespace iblkit::kernels {

// Calls run(first, count, last) for each chunk of `samples`, the last one shorter. Throws
// std::invalid_argument for a chunk of 0.
template <typename Run>
void forEachChunk(uint32_t samples, uint32_t chunk, const Run& run) {
    if (chunk == 0) throw std::invalid_argument("a chunk of 0 samples");
    for (uint32_t first = 0; first < samples; first += chunk) {
        const uint32_t count = std::min(chunk, samples - first);
        run(first, count, first + count == samples);
    }
}


// The dispatch of each kernel role, written once: what it binds, with which parameters, over
// which threads. The kernel may come from any form of its shader (the bake's, or a
// consistency path's); every command runs its GPU steps through these.

// BrdfLutGrid: the quadrature at every node of a gridSize² grid, into `grid` (2 floats a node).
void runBrdfLutGrid(Kernel& kernel, const vulkan::Buffer& grid, uint32_t gridSize);
// BrdfLutResample: every texel of `lut` interpolated from `grid`.
void runBrdfLutResample(Kernel& kernel, const vulkan::Buffer& grid, uint32_t gridSize, vulkan::Image& lut);

// SkyCube: the built-in environment into mip 0 of a cube.
void runSkyCube(Kernel& kernel, vulkan::Image& cube, const SupersampleParameters& parameters);
// EquirectToCube: a 2D panorama into mip 0 of a cube.
void runEquirectToCube(Kernel& kernel, vulkan::Image& equirect, vulkan::Image& cube, const SupersampleParameters& parameters);

// DownsampleCube: mips 1.. of a cube, each the 2x2 means of the one above.
void runDownsampleChain(Kernel& kernel, vulkan::Image& cube);

// Prefilter: one mip of `target` from `source` (sampled through `sampler`).
void runPrefilter(Kernel& kernel, vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target,
                  uint32_t mip, const PrefilterParameters& parameters);

// PrefilterChunk: one chunk of samples into `accumulator` (RGBA32F, the size of target's mip,
// 6 layers, storage); the chunk with resolve set writes the mip of `target`.
void runPrefilterChunk(Kernel& kernel, vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& accumulator,
                       vulkan::Image& target, uint32_t mip, const PrefilterChunkParameters& parameters);

// PrefilterChunk over all `samples`, `chunk` per dispatch, through an accumulator it makes.
void runPrefilterChunked(Kernel& kernel, vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target,
                         uint32_t mip, float roughness, uint32_t samples, uint32_t chunk);

// PrefilterTable: one mip of `target` from `source`, each texel summing the `entries` samples of
// `table` (float4 each, reference::prefilterSampleTable's) in its own frame.
void runPrefilterTable(Kernel& kernel, vulkan::Image& source, const vulkan::Sampler& sampler, const vulkan::Buffer& table,
                       uint32_t entries, vulkan::Image& target, uint32_t mip);

// PrefilterPyramid: one mip of `target`, each texel reading `source` along its normal at the
// reads' lods.
void runPrefilterPyramid(Kernel& kernel, vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target,
                         uint32_t mip, const PrefilterPyramidParameters& reads);

// PrefilterRing: one mip of `target`, each texel reading `source` along its normal and around a
// ring about it.
void runPrefilterRing(Kernel& kernel, vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target,
                      uint32_t mip, const PrefilterRingParameters& ring);

// ClusterCubeCS's three pyramids: RGBA32F cubes with a full mip chain, sampled and storage. With
// holdsSourceTexels, as wide as the source (mip n holds blocks of 2^n source texels across, mip 0
// its texels themselves), for PrefilterConvolution compiled with SOURCE_TEXELS_IN_PYRAMID; else
// pyramidSize(source) wide (mip n holds blocks of 2^(n+1)), and a 1x1 source, which has no block
// of more than one texel, gets 1x1 pyramids that nothing reads. With them, the solid angle of
// each of the source's texels (R32F, one face's: the same on all six), which the walk reads only
// where the pyramids do not hold the texels (a 1x1 placeholder where they do).
struct EnergyPyramid {
    vulkan::Image& energy;
    vulkan::Image& centroid;
    vulkan::Image& geometry;
    vulkan::Image& texelSolidAngle;
    bool holdsSourceTexels = false;
};

// ClusterCube: every level of `pyramid` from mip 0 of `source`, each level from the one below.
void runClusterPyramid(Kernel& kernel, vulkan::Image& source, const EnergyPyramid& pyramid);

// The pyramids' face size for a source of `sourceSize`.
uint32_t pyramidSize(uint32_t sourceSize);

// PrefilterConvolution: one mip of `target` from `source` and the pyramid runClusterPyramid made of
// it, by a kernel compiled for the pyramid's layout (with SOURCE_TEXELS_IN_PYRAMID where it holds
// the source's texels).
void runPrefilterConvolution(Kernel& kernel, vulkan::Image& source, const EnergyPyramid& pyramid, vulkan::Image& target,
                             uint32_t mip, const PrefilterConvolutionParameters& parameters);

// BrdfLut: the whole LUT image.
void runBrdfLut(Kernel& kernel, vulkan::Image& lut);

// BrdfLutChunk: one chunk into `accumulator` (RG32F, the LUT's size); resolve writes `lut`.
void runBrdfLutChunk(Kernel& kernel, vulkan::Image& accumulator, vulkan::Image& lut, const BrdfChunkParameters& parameters);

// BrdfLutChunk over all `samples`, `chunk` per dispatch, through an accumulator it makes.
void runBrdfLutChunked(Kernel& kernel, vulkan::Image& lut, uint32_t samples, uint32_t chunk);

struct ShProjection {
    std::array<glm::dvec3, 9> radiance; // projections of radiance on Y_lm, summed in double
    double solidAngle;                  // 4 pi as the texels summed it
};
// ShProject writes 9 float4 partial sums per 8x8 group (rgb, and the solid angle in w of the
// first); their total in double.
ShProjection sumShPartials(std::span<const float> partials, uint32_t groups);

// ShProject: one mip of a cube projected on bands 0-2.
ShProjection runShProject(const vulkan::VulkanContext& context, Kernel& kernel, vulkan::Image& source, uint32_t mip);

// IrradianceCube: E(n) / pi into mip 0 of `target` from a momentSize cube of radiance moments
// (reference::irradianceMoments' layout).
void runIrradianceCube(Kernel& kernel, const vulkan::Buffer& moments, uint32_t momentSize, vulkan::Image& target);

// Preview: shaded spheres and the mip strip into `image`.
struct PreviewResources {
    vulkan::Image& specular;
    vulkan::Image& irradiance;
    vulkan::Image& brdfLut;
    vulkan::Image& lobeTable;
    const vulkan::Buffer& lights;
    const vulkan::Sampler& sampler;
    vulkan::Image& image;
};
void runPreview(Kernel& kernel, const PreviewResources& resources, const PreviewParameters& parameters);

// RenderReference: one batch of Monte Carlo samples for each active pixel; the sums accumulate.
struct RenderReferenceResources {
    const vulkan::Buffer& spheres; // Common/SphereGrid.fxh's materials
    vulkan::Image& environment;
    const vulkan::Buffer& environmentCdf;
    const vulkan::Buffer& lights;
    const vulkan::Buffer& activePixels; // parameters.activeCount of them
    vulkan::Image& radianceSum;
    vulkan::Image& squareSum;
};
void runRenderReference(Kernel& kernel, const RenderReferenceResources& resources, const RenderReferenceParameters& parameters);

// RenderSplitSum: the spheres shaded with the baked maps into `image`.
struct RenderSplitSumResources {
    const vulkan::Buffer& spheres;
    vulkan::Image& specular;
    vulkan::Image& irradiance;
    vulkan::Image& brdfLut;
    vulkan::Image& lobeTable;
    vulkan::Image& transmissionTable;
    vulkan::Image& sphereTransmissionTable;
    const vulkan::Buffer& lights;
    const vulkan::Sampler& sampler;
    vulkan::Image& image;
};
void runRenderSplitSum(Kernel& kernel, const RenderSplitSumResources& resources, const RenderSplitSumParameters& parameters);

// Probe: the buffers of PbrProbeCS or LutProbeCS (which has no SampleIndices).
struct ProbeBuffers {
    const vulkan::Buffer& arguments;
    const vulkan::Buffer* sampleIndices;
    const vulkan::Buffer& results;
};
void runProbe(Kernel& kernel, const ProbeBuffers& buffers, uint32_t argumentCount);

} // namespace iblkit::kernels
