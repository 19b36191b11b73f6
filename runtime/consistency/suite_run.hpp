#pragma once

#include "consistency_suite.hpp"
#include "egl_context.hpp"
#include "gl_bake.hpp"
#include "shader_paths.hpp"

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace iblkit::consistency {

// One run of the suite: its devices, its options, the rows so far, and each kernel's forms,
// compiled once.
class SuiteRun {
public:
    SuiteRun(const vulkan::VulkanContext& vulkan, const opengl::EglContext& gl, const SuiteOptions& options)
        : vulkan(vulkan), gl(gl), options(options) {}

    const vulkan::VulkanContext& vulkan;
    const opengl::EglContext& gl;
    const SuiteOptions& options;
    std::vector<ConsistencyRow> rows;

    // Whether the options ask for the kernel's outputs (SuiteOptions::kernels).
    bool runs(const std::string& kernel) const { return options.kernels.empty() || options.kernels.contains(kernel); }
    const PathProgram& program(const std::string& kernel, ShaderPath path);
    const OpenGlForm& openGl(const std::string& kernel);

private:
    const compiler::CompileOptions& shader(const std::string& kernel) const;

    std::map<std::pair<std::string, ShaderPath>, PathProgram> programs_;
    std::map<std::string, OpenGlForm> openGlForms_;
};

// The C++ reference of an output in float (the shader's arithmetic) and in double.
struct References {
    std::vector<float> inFloat;
    std::vector<double> inDouble;
};

// What one output is: the kernel that computes it, its name in the report, and its bounds.
struct OutputSpec {
    std::string kernel;
    std::string output;
    Bounds bounds;
};

// Runs the output with the kernel's form on one Vulkan path, or on OpenGL.
using PathRun = std::function<std::vector<float>(const PathProgram&)>;
using OpenGlRun = std::function<std::vector<float>(const OpenGlForm&)>;

// The float reference's row, then one row per path, each judged against both references; nothing,
// not even the references, when the options leave the kernel out.
void addOutput(SuiteRun& run, const OutputSpec& spec, const std::function<References()>& references,
               const PathRun& vulkanRun, const OpenGlRun& openGlRun);

// One path's values judged against the references: a row, passed when within the spec's bounds.
void addJudgedRow(SuiteRun& run, const OutputSpec& spec, std::string path, const std::vector<float>& gpu, const References& references);

// For an output with no C++ reference: path a's result is the reference of the other paths.
void addOutputAgainstPathA(SuiteRun& run, const OutputSpec& spec, const PathRun& vulkanRun, const OpenGlRun& openGlRun);

// The outputs of each group of kernels (sampled_outputs.cpp, quadrature_outputs.cpp, cube_outputs.cpp,
// convolution_outputs.cpp, filtered_outputs.cpp, probe_outputs.cpp).
void addSampledLutOutputs(SuiteRun& run);
void addSampledPrefilterOutputs(SuiteRun& run);
void addQuadratureLutOutput(SuiteRun& run);
void addGridLutOutputs(SuiteRun& run);
void addFitLutOutput(SuiteRun& run);
void addChunkedLutOutput(SuiteRun& run);
void addChunkedPrefilterOutput(SuiteRun& run);
void addSkyOutputs(SuiteRun& run);
void addCubeOutputs(SuiteRun& run); // the panorama's resampling, the mip chain, the harmonics, irradiance
void addConvolutionOutputs(SuiteRun& run);
void addFilteredOutputs(SuiteRun& run);
void addPreviewOutput(SuiteRun& run);
// ForwardSpheres drawn on every path of the run harness, against SplitSumSpheresCS's image (forward_outputs.cpp).
void addForwardPassOutput(SuiteRun& run);
void addProbeOutputs(SuiteRun& run);

// Every output that reads run.options.environment, in the suite's order.
void addEnvironmentOutputs(SuiteRun& run);

} // namespace iblkit::consistency
