// The convolution method's kernels: the energy pyramid of the test environment, and one
// prefiltered cube convolved from it.
#include "cluster_convolution.hpp"
#include "convolution_bake.hpp"
#include "kernels/convolution_method.hpp"
#include "kernels/kernel_steps.hpp"
#include "suite_run.hpp"

#include <fmt/core.h>

namespace iblkit::consistency {
namespace {

// The reference's levels from `first` up: its level 0 holds single texels, which only a pyramid
// as wide as the source keeps.
template <typename T>
std::vector<T> levelTexels(const std::vector<std::vector<glm::vec<4, T>>>& levels, size_t first) {
    std::vector<T> values;
    for (size_t level = first; level < levels.size(); ++level)
        for (const auto& texel : levels[level]) values.insert(values.end(), {texel.x, texel.y, texel.z, texel.w});
    return values;
}

template <typename T>
std::vector<T> flattened(const reference::ClusterPyramid<T>& pyramid) {
    std::vector<T> values;
    for (const auto* levels : {&pyramid.energy, &pyramid.centroid, &pyramid.geometry}) {
        const auto texels = levelTexels(*levels, 1);
        values.insert(values.end(), texels.begin(), texels.end());
    }
    return values;
}

PyramidTexels pyramidTexels(const MippedCube& source, const reference::ClusterPyramid<float>& pyramid, bool holdsSourceTexels) {
    const auto cube = [&](const auto& levels) {
        if (holdsSourceTexels) return MippedCube{pyramid.size, uint32_t(levels.size()), levelTexels(levels, 0)};
        if (levels.size() < 2) return MippedCube{1, 1, std::vector<float>(6 * 4, 0.f)}; // a 1x1 source's: never read
        return MippedCube{kernels::pyramidSize(pyramid.size), uint32_t(levels.size() - 1), levelTexels(levels, 1)};
    };
    std::vector<float> solidAngle; // the reference's level 0 holds each texel's, face by face
    for (size_t texel = 0; texel < size_t(pyramid.size) * pyramid.size; ++texel) solidAngle.push_back(pyramid.energy[0][texel].w);
    return {source, cube(pyramid.energy), cube(pyramid.centroid), cube(pyramid.geometry), solidAngle, holdsSourceTexels};
}

void addClusterOutput(SuiteRun& run, const MippedCube& cube, const reference::ClusterPyramid<float>& inFloat,
                      const reference::ClusterPyramid<double>& inDouble) {
    addOutput(run, {"ClusterCubeCS", fmt::format("energy, centroid, geometry pyramids of {}²", cube.size), clusterBounds()},
              [&] { return References{flattened(inFloat), flattened(inDouble)}; },
              [&](const PathProgram& program) { return gpuClusterPyramid(run.vulkan, program, cube); },
              [&](const OpenGlForm& form) { return glClusterPyramid(run.gl, form, cube); });
}

// The lobe weighted by N·L (0), as the documents' prefilter, or by G1 (1), as the kit's recipe; by
// the manifest's walk over a half-width pyramid, or by the bake's over one holding the source's
// texels (kConvolutionInPyramidShader).
void addConvolutionOutput(SuiteRun& run, const MippedCube& cube, const reference::ClusterPyramid<float>& inFloat,
                          const reference::ClusterPyramid<double>& inDouble, uint32_t weighting, bool holdsSourceTexels) {
    const auto& options = run.options;
    const float roughness = options.convolutionRoughness;
    const auto plan = kernels::planConvolution(inFloat.size, roughness, options.convolutionBudget);
    const reference::ConvolutionTree tree{plan.topLevel, plan.fineLevel, plan.refine, plan.horizonLevel, weighting};
    const kernels::PrefilterConvolutionParameters parameters{roughness,  plan.topLevel,      plan.fineLevel,
                                                             plan.refine, plan.horizonLevel, weighting};
    const uint32_t outSize = options.convolutionOutSize;
    const auto pyramid = pyramidTexels(cube, inFloat, holdsSourceTexels);
    const auto output = fmt::format("{}² at roughness {} from the {}² pyramid, {} terms per texel{}", outSize, roughness,
                                    inFloat.size, options.convolutionBudget, weighting ? ", lobe weighted by G1" : "");
    const std::string shader = holdsSourceTexels ? kConvolutionInPyramidShader : "PrefilterConvolutionCS";
    addOutput(run, {shader, output, convolutionBounds()},
              [&] { return References{reference::convolvePrefilter(inFloat, roughness, outSize, tree),
               reference::convolvePrefilter(inDouble, double(roughness), outSize, tree)}; },
              [&](const PathProgram& program) {
                  return gpuPrefilterConvolution(run.vulkan, program, pyramid, outSize, parameters);
              },
              [&](const OpenGlForm& form) { return glPrefilterConvolution(run.gl, form, pyramid, outSize, parameters); });
}

} // namespace

void addConvolutionOutputs(SuiteRun& run) {
    if (!run.runs("ClusterCubeCS") && !run.runs("PrefilterConvolutionCS") && !run.runs(kConvolutionInPyramidShader)) return;
    const auto cube = environmentCube(run.options.environment, run.options.convolutionSize, 1);
    const auto inFloat = reference::clusterPyramid<float>(cube.texels, cube.size);
    const auto inDouble = reference::clusterPyramid<double>(cube.texels, cube.size);
    addClusterOutput(run, cube, inFloat, inDouble);
    for (const bool holdsSourceTexels : {false, true}) {
        if (holdsSourceTexels && !kernels::pyramidHoldsSourceTexels(cube.size)) continue; // a single texel is a face
        addConvolutionOutput(run, cube, inFloat, inDouble, 0, holdsSourceTexels);
        addConvolutionOutput(run, cube, inFloat, inDouble, 1, holdsSourceTexels);
    }
}

} // namespace iblkit::consistency
