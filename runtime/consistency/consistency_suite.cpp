#include "consistency_suite.hpp"

#include "gl_bake.hpp"
#include "gpu_bake.hpp"
#include "reference_bake.hpp"
#include "shader_manifest.hpp"
#include "shader_paths.hpp"

#include <fmt/core.h>

#include <functional>
#include <map>

#include <glslang/build_info.h>
#include <spirv-tools/libspirv.h>

namespace iblkit::consistency {
namespace {

bool withinBounds(const ErrorStats& vsFloat, const ErrorStats& vsDouble, const Bounds& bounds) {
    return vsFloat.nonFinite == 0 && vsFloat.maxAbsolute <= bounds.maxVsFloat && vsFloat.rms <= bounds.rmsVsFloat &&
           vsDouble.maxAbsolute <= bounds.maxVsDouble && vsDouble.rms <= bounds.rmsVsDouble;
}

constexpr const char* kOpenGlPath = "d. HLSL → SPIR-V → GLSL 450 on OpenGL 4.5 (EGL)";

// Runs one output on every Vulkan path and on OpenGL.
using PathRun = std::function<std::vector<float>(ShaderPath)>;
using OpenGlRun = std::function<std::vector<float>()>;

void addOutput(std::vector<ConsistencyRow>& rows, const std::string& output, const std::vector<float>& floatReference,
               const std::vector<double>& doubleReference, const Bounds& bounds, const PathRun& vulkanRun,
               const OpenGlRun& openGlRun) {
    rows.push_back({"f. C++ reference, float", output, {}, measureError(floatReference, doubleReference), bounds, true, true});
    const auto add = [&](std::string path, const std::vector<float>& gpu) {
        const auto vsFloat = measureError(gpu, floatReference);
        const auto vsDouble = measureError(gpu, doubleReference);
        rows.push_back({std::move(path), output, vsFloat, vsDouble, bounds, false, withinBounds(vsFloat, vsDouble, bounds)});
    };
    for (const auto path : kVulkanPaths) add(std::string(pathName(path)), vulkanRun(path));
    add(kOpenGlPath, openGlRun());
}

} // namespace

// Each bound is twice the largest error measured on lavapipe (docs/consistency.md), rounded
// up; boundsRationale() says why the errors are what they are.
Bounds lutBounds(uint32_t size) {
    if (size <= 32) return {5e-5, 1.5e-6, 5e-5, 1.5e-6};
    return {1.2e-2, 4e-5, 2e-3, 6e-6};
}

Bounds prefilterBounds() { return {1.5e-3, 2e-5, 1.5e-3, 6e-5}; }

std::string boundsRationale() {
    return "Every bound is twice the largest error measured on lavapipe, rounded up; a row must keep both its largest "
           "absolute error and its RMS error within them, against both references.\n\n"
           "- **LUT 32²** (max 5e-5, RMS 1.5e-6): values lie in [0, 1]. The GPU and the float reference do the same float "
           "operations, but llvmpipe's sqrt, sin, cos, pow and normalize differ from glibc's in their last bits; over "
           "1024 samples the GPU ends at most 2.2e-5 from either reference — the float reference itself is 2.6e-5 "
           "from the double one.\n"
           "- **LUT 512²** (max 1.2e-2 against float, 2e-3 against double; RMS 4e-5 and 6e-6): the 512² LUT has a "
           "column at N·V = 1/1024, where IntegrateBRDF is ill-conditioned: whether a sample's N·L is above 0 after "
           "the cancellation in 2(V·H)H − V depends on the last bits, and such a sample weighs G·V·H / (N·H·N·V), of "
           "order 1/N·V. The float reference, with glibc's rounding, is further from the double truth (6.9e-3) than "
           "the GPU is (9.6e-4), hence the wider bound against it. The RMS bounds stay tight: a porting bug moves "
           "every texel (k = (r+1)²/8 changes LUT values by 1e-2 and more at most roughnesses).\n"
           "- **Prefilter** (max 1.5e-3, RMS 2e-5 against float and 6e-5 against double): radiance reaches ~40 at the "
           "test sun; errors of 1e-5 relative come from float rounding of the 1024-sample sums (at roughness 0 all "
           "1024 samples are the same direction, so the float sum's rounding shows most against double) and from the "
           "texture unit's bilinear weights against the reference's exact ones. A swapped face or a transposed tangent "
           "frame moves texels by 1e-1 to 10.\n";
}

SuiteOptions defaultSuiteOptions(const std::string& manifest, uint32_t sampleCount) {
    SuiteOptions options;
    options.sampleCount = sampleCount;
    options.lutShader = compiler::manifestShaderOptions(manifest, "PrecomputedBrdfCS");
    options.lutShader.imageFormats["Precomputed"] = "rg32f";
    options.prefilterShader = compiler::manifestShaderOptions(manifest, "PrefilterSpecularCS");
    for (auto* shader : {&options.lutShader, &options.prefilterShader})
        shader->defines["SAMPLE_COUNT"] = std::to_string(sampleCount);
    return options;
}

std::string_view openGlPathName() { return kOpenGlPath; }

ConsistencyResult runConsistency(const vulkan::VulkanContext& context, const SuiteOptions& options) {
    ConsistencyResult result;
    auto& rows = result.rows;
    const opengl::EglContext gl;
    result.openGlRenderer = gl.renderer();
    const auto lutForm = openGlForm(options.lutShader);
    const auto prefilterForm = openGlForm(options.prefilterShader);
    std::map<ShaderPath, PathProgram> lutPrograms, prefilterPrograms; // each path compiled once
    for (const auto path : kVulkanPaths) {
        lutPrograms.emplace(path, compileForPath(path, options.lutShader));
        prefilterPrograms.emplace(path, compileForPath(path, options.prefilterShader));
    }
    for (const uint32_t size : options.lutSizes) {
        addOutput(rows, fmt::format("LUT {}²", size), reference::referenceBrdfLut<float>(size, options.sampleCount),
                  reference::referenceBrdfLut<double>(size, options.sampleCount), lutBounds(size),
                  [&](ShaderPath path) { return gpuBrdfLut(context, lutPrograms.at(path), size); },
                  [&] { return glBrdfLut(gl, lutForm, size); });
    }
    const auto environment = reference::CubeEnvironment::testEnvironment(options.environmentSize);
    for (const float roughness : options.roughnesses) {
        const uint32_t size = options.prefilterSize;
        addOutput(rows, fmt::format("prefilter {}² r={}", size, roughness),
                  reference::referencePrefilter<float>(environment, roughness, size, options.sampleCount),
                  reference::referencePrefilter<double>(environment, double(roughness), size, options.sampleCount),
                  prefilterBounds(),
                  [&](ShaderPath path) { return gpuPrefilter(context, prefilterPrograms.at(path), environment, roughness, size); },
                  [&] { return glPrefilter(gl, prefilterForm, environment, roughness, size); });
    }
    return result;
}

std::string renderMarkdown(const std::vector<ConsistencyRow>& rows, const vulkan::VulkanContext& context,
                           const std::string& openGlRenderer, const SuiteOptions& options, const std::string& command) {
    std::string text = "# Consistency: every form of the seed shaders against the C++ reference\n\n";
    text += fmt::format("Made by `{}`; do not edit.\n\n", command);
    const auto& device = context.deviceInfo();
    text += fmt::format("- Device: {} ({}, Vulkan {}), driver {}\n", device.name, device.type, device.apiVersion, device.driver);
    text += fmt::format("- OpenGL: {}\n", openGlRenderer);
    text += fmt::format("- glslang {}.{}.{}, SPIRV-Tools {}, Vulkan headers {}\n", GLSLANG_VERSION_MAJOR, GLSLANG_VERSION_MINOR,
                        GLSLANG_VERSION_PATCH, spvSoftwareVersionString(), VK_HEADER_VERSION);
    text += fmt::format("- {} samples per texel; the LUT written as R32G32_SFLOAT; the prefilter over a {}² procedural "
                        "environment (sky, horizon, ground, a soft sun of radiance ~40), sampled linearly at mip 0\n",
                        options.sampleCount, options.environmentSize);
    text += "- Errors: the largest absolute error, the largest distance in float32 ULPs, the RMS error, and the count of "
            "NaN and infinite GPU values; against the C++ reference computed in float (f) and in double (g). "
            "A path passes when it has no NaN or infinity and its largest and RMS errors against both are within the "
            "bounds (max / RMS). The row \"f.\" is the float reference against the double one, shown for scale.\n"
            "\n";
    text += "| output | path | max abs vs f | max ULP vs f | RMS vs f | max abs vs g | max ULP vs g | RMS vs g | NaN/Inf "
            "| bounds vs f | bounds vs g | pass |\n";
    text += "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& row : rows) {
        const auto cell = [&](double value, const char* format) {
            return row.isReference ? std::string("—") : fmt::format(fmt::runtime(format), value);
        };
        text += fmt::format("| {} | {} | {} | {} | {} | {:.2e} | {:.0f} | {:.2e} | {} | {} | {} | {} |\n",
                            row.output, row.path, cell(row.vsFloat.maxAbsolute, "{:.2e}"), cell(row.vsFloat.maxUlp, "{:.0f}"),
                            cell(row.vsFloat.rms, "{:.2e}"), row.vsDouble.maxAbsolute, row.vsDouble.maxUlp, row.vsDouble.rms,
                            row.vsDouble.nonFinite, // both columns measure the same GPU values
                            row.isReference ? std::string("—")
                                            : fmt::format("{:.1e} / {:.1e}", row.bounds.maxVsFloat, row.bounds.rmsVsFloat),
                            row.isReference ? std::string("—")
                                            : fmt::format("{:.1e} / {:.1e}", row.bounds.maxVsDouble, row.bounds.rmsVsDouble),
                            row.isReference ? "—" : (row.passed ? "yes" : "**no**"));
    }
    text += "\n## The bounds\n\n" + boundsRationale();
    return text;
}

} // namespace iblkit::consistency
