#pragma once

#include "compile_options.hpp"
#include "reflection.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace iblkit::kernels {

// What a kernel does in a bake: the resources it binds and the parameter struct it takes
// (kernel_parameters.hpp), whichever HLSL implements it.
enum class KernelRole {
    BrdfLut,        // RWTexture2D Precomputed; SAMPLE_COUNT
    BrdfLutChunk,   // + Accumulated; BrdfChunkParameters
    BrdfLutGrid,    // RWStructuredBuffer Grid (the nodes of Common/LutGrid.fxh); LutGridParameters; SAMPLE_COUNT
    BrdfLutResample, // StructuredBuffer Grid -> RWTexture2D Precomputed; LutGridParameters
    Prefilter,      // EnvMap + EnvMapSampler -> Prefiltered (one mip); PrefilterParameters
    PrefilterChunk, // + Accumulated; PrefilterChunkParameters
    PrefilterTable, // EnvMap + EnvMapSampler + SampleTable -> Prefiltered (one mip); PrefilterTableParameters
    PrefilterPyramid, // EnvMap + EnvMapSampler -> Prefiltered (one mip); PrefilterPyramidParameters; READ_COUNT
    PrefilterRing,  // EnvMap + EnvMapSampler -> Prefiltered (one mip); PrefilterRingParameters; RING_COUNT
    ClusterCube,    // Source -> Energy + Centroid + Geometry (one pyramid level); ClusterParameters
    PrefilterConvolution, // Energy + Centroid + Geometry -> Prefiltered (one mip); PrefilterConvolutionParameters
    SkyCube,        // the built-in environment into mip 0 of a cube; SupersampleParameters
    EquirectToCube, // SupersampleParameters
    DownsampleCube,
    ShProject,
    IrradianceCube,
    Preview,
    RenderReference, // Environment + EnvironmentCdf + Lights -> RadianceSum + SquareSum; RenderReferenceParameters
    RenderSplitSum,  // Specular + IrradianceMap + BrdfLut -> SplitSum; RenderSplitSumParameters
    Probe,          // StructuredBuffer Arguments (+ SampleIndices) -> RWStructuredBuffer Results; ProbeParameters
};

std::string_view roleName(KernelRole role);

struct KernelEntry {
    std::string name; // the shader's name in hlsl/shaders.json
    KernelRole role;
    std::vector<std::string> methods; // for the LUT and prefilter roles ("document"); a kernel may serve several
    bool belongsTo(std::string_view method) const;
    bool document;        // the documents' faithful transcription (hlsl/document/), frozen
    compiler::CompileOptions options; // as the manifest gives them, reading the built-in hlsl/
};

// hlsl/ and hlsl/shaders.json as they were when the program was built, by path
// ("hlsl/document/Common/PBR.fxh").
const std::map<std::string, std::string>& embeddedShaderFiles();

// Every kernel of the built-in hlsl/shaders.json, in its order.
const std::vector<KernelEntry>& kernelTable();
// Throws std::out_of_range naming what is missing.
const KernelEntry& kernelNamed(std::string_view name);
const KernelEntry& kernelFor(KernelRole role, std::string_view method = {});
// The methods that have a kernel of `role`, in table order.
std::vector<std::string> methodsOf(KernelRole role);

struct KernelProgram {
    std::vector<uint32_t> spirv;
    compiler::ShaderReflection reflection;
};

// Shader files to compile from: the built-in hlsl/, with some files replaced (by path).
using ShaderFiles = std::map<std::string, std::string>;

// The kernel's compile options with its source and includes served from `files`.
compiler::CompileOptions optionsReading(const KernelEntry& kernel, const ShaderFiles& files = embeddedShaderFiles());

// Compiles a kernel from `files` with the kit's compiler, adding defines and storage image
// formats to the manifest's. Throws compiler::CompileError.
KernelProgram compileKernel(const KernelEntry& kernel, const std::map<std::string, std::string>& defines = {},
                            const std::map<std::string, std::string>& imageFormats = {},
                            const ShaderFiles& files = embeddedShaderFiles());

} // namespace iblkit::kernels
