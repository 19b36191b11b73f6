#pragma once

#include "compile_options.hpp"
#include "error_stats.hpp"
#include "suite_environment.hpp"
#include "context_options.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace iblkit::bake {
class BakeProgress;
}

namespace iblkit::consistency {

inline constexpr uint32_t kSuiteLutFitDegree = 5; // BrdfLutFitCS's SAMPLE_COUNT in the suite

struct SuiteOptions {
    // PrecomputedBrdfCS and PrefilterSpecularCS (the documents' shaders).
    std::vector<uint32_t> lutSizes{512, 32};
    uint32_t quadratureLutSize = 128; // BrdfLutQuadratureCS at its default nodes per panel, BrdfLutResampleCS, BrdfLutFitCS
    uint32_t lutGridSize = 32;        // BrdfLutGridCS's nodes per side
    uint32_t prefilterSize = 32;
    uint32_t environmentSize = 64;
    std::vector<float> roughnesses{0.0f, 0.25f, 0.5f, 1.0f};
    uint32_t sampleCount = 1024;
    // Their chunked twins: the same sampleCount in dispatches of chunkSamples (the last one
    // shorter), the LUT at chunkLutSize, the prefilter at prefilterSize and chunkRoughness.
    uint32_t chunkSamples = 300;
    uint32_t chunkLutSize = 32;
    float chunkRoughness = 0.5f;
    // The cube kernels: a panoramaWidth x panoramaWidth/2 panorama onto cubeSize faces with
    // supersample² reads per texel; the test environment at mipChainSize downsampled to 1x1; its
    // mip 1 projected on the harmonics and convolved into an irradianceSize cube.
    uint32_t panoramaWidth = 128;
    uint32_t cubeSize = 16;
    uint32_t supersample = 2;
    uint32_t mipChainSize = 32;
    uint32_t irradianceSize = 8;
    // The convolution method: the test environment's pyramid at convolutionSize, and from it a
    // convolutionOutSize cube at convolutionRoughness with convolutionBudget terms per texel.
    uint32_t convolutionSize = 16, convolutionOutSize = 8;
    float convolutionRoughness = 0.5f;
    uint32_t convolutionBudget = 64;
    // PreviewCS: columns x rows spheres of cellSize pixels over a cubeSize specular cube.
    uint32_t previewColumns = 4, previewRows = 2, previewCellSize = 16;
    // What the cube kernels read.
    SuiteEnvironment environment = testSuiteEnvironment();
    // The shaders under test, by their name in the manifest: every kernel of hlsl/shaders.json,
    // or the same from a copy that a test has broken.
    std::map<std::string, compiler::CompileOptions> shaders;
    // The kernels whose outputs the suite runs, by name; empty: every kernel.
    std::set<std::string> kernels;
};

// PrefilterConvolutionCS as bakes of sources up to 512² run it, compiled with
// SOURCE_TEXELS_IN_PYRAMID over a pyramid that holds the source's texels: a shader of the suite's
// own beside the manifest's, judged on every path as they are.
inline constexpr const char* kConvolutionInPyramidShader = "PrefilterConvolutionCS, SOURCE_TEXELS_IN_PYRAMID";

// ForwardSpheres.hlsl, the preview's spheres drawn as meshes (vertex and pixel shaders), beside
// the manifest's kernels: judged on every path of the run harness against SplitSumSpheresCS.
inline constexpr const char* kForwardPassShader = "ForwardSpheres";

// The options the suite runs every kernel with: the manifest's (or, when there is no such file,
// those of the hlsl/ built into the program), with SAMPLE_COUNT set and the LUTs written as
// R32G32_SFLOAT (so that the comparison measures arithmetic, not storage); and
// kConvolutionInPyramidShader.
SuiteOptions defaultSuiteOptions(const std::string& manifest = "hlsl/shaders.json", uint32_t sampleCount = 1024);

// Bounds on the largest absolute error and the RMS error of a path, against each reference.
struct Bounds {
    double maxVsFloat, rmsVsFloat, maxVsDouble, rmsVsDouble;
};

struct ConsistencyRow {
    std::string kernel; // the shader's name in the manifest
    std::string path;
    std::string output;
    ErrorStats vsFloat;
    ErrorStats vsDouble;
    Bounds bounds;
    bool isReference; // the reference itself (against the double one): shown, not judged
    bool passed;
    // A divergence the kit knows and tracks (knownDivergence): the row is expected to fail, and
    // one that passes means the cause is gone and the entry should go.
    std::string knownIssue = {};
    // Against the double: the largest error of the colour values (alpha, every fourth, aside) over
    // the largest of them, for comparing environments of any brightness (iblkit stress).
    double colourError = 0;

    bool asExpected() const { return knownIssue.empty() ? passed : !passed; }
};

// Every path of every output of every kernel — the four Vulkan paths and d, the GLSL form on
// OpenGL 4.5 through EGL — against the C++ reference in float and in double; the first row of
// each output is the float reference itself against the double one. PreviewCS has no C++
// reference: its paths are compared with path a, whose row comes first.
struct ConsistencyResult {
    std::vector<ConsistencyRow> rows;
    std::string openGlRenderer;
};
// `progress`, when given, gets a step per group of outputs.
ConsistencyResult runConsistency(const vulkan::VulkanContext& context, const SuiteOptions& options,
                                 bake::BakeProgress* progress = nullptr);

// The bounds of each output, and why each is those numbers (boundsRationale).
Bounds lutBounds(uint32_t size);
Bounds quadratureLutBounds();
Bounds lutGridBounds();
Bounds lutResampleBounds();
Bounds lutFitBounds();
Bounds prefilterBounds();
Bounds lutChunkBounds();
Bounds prefilterChunkBounds();
Bounds skyBounds();
Bounds equirectBounds();
Bounds downsampleBounds();
Bounds shBounds();
Bounds irradianceBounds();
Bounds clusterBounds();
Bounds convolutionBounds();
Bounds filteredBounds();
Bounds tableBounds();
Bounds pyramidBounds();
Bounds ringBounds();
Bounds previewBounds();
Bounds pbrProbeBounds();
Bounds lutProbeBounds();
Bounds bsdfProbeBounds();
Bounds renderReferenceBounds();
Bounds splitSumSpheresBounds();
Bounds forwardPassBounds();
std::string boundsRationale();
// Why `kernel` on the path named `path` is known to diverge, or empty.
std::string knownDivergence(const std::string& kernel, const std::string& path);

std::string renderMarkdown(const std::vector<ConsistencyRow>& rows, const vulkan::VulkanContext& context,
                           const std::string& openGlRenderer, const SuiteOptions& options, const std::string& command);

// The name of path d in the rows.
std::string_view openGlPathName();

} // namespace iblkit::consistency
