#include "consistency_suite.hpp"

#include "bake_progress.hpp"
#include "kernels/convolution_method.hpp"
#include "kernels/kernel_table.hpp"
#include "kernels/lut_methods.hpp"
#include "shader_manifest.hpp"
#include "render_outputs.hpp"
#include "suite_run.hpp"

#include <filesystem>

namespace iblkit::consistency {
namespace {

constexpr const char* kOpenGlPath = "d. HLSL → SPIR-V → GLSL 450 on OpenGL 4.5 (EGL)";

bool isSampled(kernels::KernelRole role) {
    using enum kernels::KernelRole;
    return role == BrdfLut || role == BrdfLutChunk || role == Prefilter || role == PrefilterChunk;
}

} // namespace

SuiteOptions defaultSuiteOptions(const std::string& manifest, uint32_t sampleCount) {
    SuiteOptions options;
    options.sampleCount = sampleCount;
    // Outside a source tree there is no hlsl/shaders.json: the copy built into the program serves.
    std::error_code error;
    const bool onDisk = std::filesystem::exists(manifest, error);
    for (const auto& kernel : kernels::kernelTable()) {
        auto shader = onDisk ? compiler::manifestShaderOptions(manifest, kernel.name) : kernels::optionsReading(kernel);
        if (isSampled(kernel.role)) shader.defines["SAMPLE_COUNT"] = std::to_string(sampleCount);
        if (kernel.belongsTo(kernels::kQuadratureLutMethod))
            shader.defines["SAMPLE_COUNT"] = std::to_string(kernels::kDefaultQuadratureNodes);
        if (kernel.belongsTo(kernels::kFitLutMethod)) shader.defines["SAMPLE_COUNT"] = std::to_string(kSuiteLutFitDegree);
        if (kernel.role == kernels::KernelRole::BrdfLut || kernel.role == kernels::KernelRole::BrdfLutResample)
            shader.imageFormats["Precomputed"] = "rg32f";
        if (kernel.role == kernels::KernelRole::BrdfLutChunk)
            shader.imageFormats = {{"Precomputed", "rg32f"}, {"Accumulated", "rg32f"}};
        options.shaders.emplace(kernel.name, std::move(shader));
    }
    auto inPyramid = options.shaders.at("PrefilterConvolutionCS");
    inPyramid.defines[kernels::kSourceTexelsInPyramidDefine] = "1";
    options.shaders.emplace(kConvolutionInPyramidShader, std::move(inPyramid));
    auto forward = options.shaders.at("SplitSumSpheresCS"); // its folder, include folders and files
    forward.source = forward.source.parent_path() / "ForwardSpheres.hlsl";
    if (forward.sourceText) forward.sourceText = forward.virtualFiles.at(forward.source.generic_string());
    options.shaders.emplace(kForwardPassShader, std::move(forward));
    return options;
}

std::string_view openGlPathName() { return kOpenGlPath; }

ConsistencyResult runConsistency(const vulkan::VulkanContext& context, const SuiteOptions& options,
                                 bake::BakeProgress* progress) {
    const opengl::EglContext gl;
    SuiteRun run(context, gl, options);
    const std::pair<const char*, void (*)(SuiteRun&)> groups[] = {
        {"sampled lut", addSampledLutOutputs},     {"sampled prefilter", addSampledPrefilterOutputs},
        {"quadrature lut", addQuadratureLutOutput}, {"grid lut", addGridLutOutputs},
        {"fitted lut", addFitLutOutput},            {"chunked lut", addChunkedLutOutput},
        {"chunked prefilter", addChunkedPrefilterOutput}, {"sky", addSkyOutputs},
        {"cube", addCubeOutputs},                   {"convolution", addConvolutionOutputs},
        {"filtered", addFilteredOutputs},           {"preview", addPreviewOutput},
        {"render", addRenderOutputs},               {"forward pass", addForwardPassOutput},
        {"probes", addProbeOutputs}};
    for (const auto& [name, add] : groups) {
        if (progress) progress->begin(name);
        add(run);
        if (progress) progress->end();
    }
    return {std::move(run.rows), gl.renderer()};
}

void addEnvironmentOutputs(SuiteRun& run) {
    addSampledPrefilterOutputs(run);
    addChunkedPrefilterOutput(run);
    addCubeOutputs(run);
    addConvolutionOutputs(run);
    addFilteredOutputs(run);
    addPreviewOutput(run);
    addRenderOutputs(run);
}

} // namespace iblkit::consistency
