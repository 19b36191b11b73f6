#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace iblkit::kernels {

// A cbuffer's members by their HLSL name, as packBlock takes them.
using NamedValues = std::map<std::string, std::vector<double>>;

// One typed struct per kernel role; members() names each field as the role's HLSL declares it.
struct PrefilterParameters {
    float roughness = 0;
    NamedValues members() const;
};

struct PrefilterChunkParameters {
    float roughness = 0;
    uint32_t firstSample = 0;
    uint32_t chunkSamples = 0;
    bool resolve = false; // the last chunk: also write the ratio of the sums
    NamedValues members() const;
};

struct PrefilterTableParameters {
    uint32_t sampleCount = 0; // entries of the sample table
    NamedValues members() const;
};

// reference::fitPyramidReads's reads: 1 to 4 lods and as many weights (members() throws
// std::invalid_argument otherwise).
struct PrefilterPyramidParameters {
    std::vector<float> lods, weights;
    NamedValues members() const;
};

// PrefilterRingCS's Ring (reference::PyramidRing).
struct PrefilterRingParameters {
    float centreLod = 0, ringLod = 0, cosAngle = 1, centreWeight = 1;
    NamedValues members() const;
};

// BrdfLutGrid and BrdfLutResample: the quadrature grid's nodes per side.
struct LutGridParameters {
    uint32_t gridSize = 0;
    NamedValues members() const;
};

struct ClusterParameters {
    uint32_t level = 0;
    NamedValues members() const;
};

struct PrefilterConvolutionParameters {
    float roughness = 0;
    uint32_t topLevel = 0, fineLevel = 0;
    float refine = 0;
    uint32_t horizonLevel = 0;
    uint32_t weighting = 0; // shading::LobeWeighting: 0 N·L, 1 G1
    NamedValues members() const;
};

struct BrdfChunkParameters {
    uint32_t firstSample = 0;
    uint32_t chunkSamples = 0;
    bool resolve = false;
    NamedValues members() const;
};

// SkyCube and EquirectToCube: evaluations (reads) per cube texel along each axis.
struct SupersampleParameters {
    uint32_t supersample = 1;
    NamedValues members() const;
};

// DownsampleCube and ShProject read one mip of their source.
struct SourceMipParameters {
    uint32_t sourceMip = 0;
    NamedValues members() const;
};

// IrradianceCube: the face size of the moment cube it sums.
struct IrradianceParameters {
    uint32_t momentSize = 0;
    NamedValues members() const;
};

// How a shading recipe reads the maps (Common/ImageBasedLighting.fxh's IblRecipe, but for the
// mip count, which each kernel names beside its own fields).
struct IblRecipeParameters {
    uint32_t specularSize = 0, lodMapping = 0;
    float lodParameter = 1;
    uint32_t direction = 0, lookup = 0, lightCount = 0, lightLevel = 0;
    void addTo(NamedValues& values) const;
};

struct PreviewParameters {
    uint32_t columns = 0, rows = 0, cellSize = 0, specularMips = 0, stripPanelWidth = 0;
    float exposure = 1;
    IblRecipeParameters recipe;
    NamedValues members() const;
};

// RenderReferenceCS: the sphere grid (Common/SphereGrid.fxh), which samples this dispatch adds (to
// how many active pixels),
// the run's seed, the lights, and the face size and mip of the environment's sampling distribution.
struct RenderReferenceParameters {
    uint32_t columns = 0, cellSize = 0;
    uint32_t firstSample = 0, sampleCount = 0, seed = 0;
    uint32_t lightCount = 0, distributionSize = 0, environmentMip = 0;
    uint32_t activeCount = 0;
    NamedValues members() const;
};

// SplitSumSpheresCS: the sphere grid, the specular cube's mips and face size, the shading
// recipe (Common/ImageBasedLighting.fxh's IblRecipe) and how it shades glass.
struct RenderSplitSumParameters {
    uint32_t columns = 0, cellSize = 0, specularMips = 0;
    IblRecipeParameters recipe;
    uint32_t glassTransmission = 0; // IBL_GLASS_SCHLICK, IBL_GLASS_TABULATED, IBL_GLASS_SPHERE
    float glassRoughnessScale = 1;
    NamedValues members() const;
};

// PbrProbeCS and LutProbeCS: how many arguments to evaluate.
struct ProbeParameters {
    uint32_t argumentCount = 0;
    NamedValues members() const;
};

} // namespace iblkit::kernels
