#include "probe_bake.hpp"

#include "gl_support.hpp"
#include "kernels/kernel.hpp"
#include "kernels/kernel_steps.hpp"
#include "lut_quadrature.hpp"
#include "pbr.hpp"

#include <span>

namespace iblkit::consistency {
namespace {

constexpr uint32_t kQuadratureNodes = 7; // LutProbeCS's SAMPLE_COUNT in hlsl/shaders.json
constexpr uint32_t kDocumentSamples = 1024; // PbrProbeCS's SAMPLE_COUNT in hlsl/shaders.json

size_t resultBytes(const ProbeArguments& arguments, uint32_t resultsPerArgument) {
    return arguments.values.size() * resultsPerArgument * sizeof(glm::vec4);
}

// PbrProbeCS's ProbeNormals, the same floats.
template <typename T>
reference::vec3<T> probeNormal(size_t index) {
    static const glm::vec3 normals[5] = {{0.f, 0.f, 1.f},
                                         {0.f, 1.f, 0.f},
                                         {0.f, 0.9989995f, 0.04472135f},
                                         {0.f, -0.99900013f, 0.04470727f},
                                         {0.57735026f, 0.57735026f, 0.57735026f}};
    return reference::vec3<T>(normals[index % 5]);
}

} // namespace

std::vector<float> gpuProbe(const vulkan::VulkanContext& context, const PathProgram& program,
                            const ProbeArguments& arguments, uint32_t resultsPerArgument) {
    kernels::Kernel kernel(context, program);
    const auto values = std::as_bytes(std::span(arguments.values));
    const auto argumentBuffer = vulkan::storageBuffer(context, values, "Arguments");
    const auto results = vulkan::storageBuffer(context, {}, "Results", resultBytes(arguments, resultsPerArgument));
    std::optional<vulkan::Buffer> sampleIndices;
    if (!arguments.sampleIndices.empty()) {
        const auto indices = std::as_bytes(std::span(arguments.sampleIndices));
        sampleIndices.emplace(vulkan::storageBuffer(context, indices, "SampleIndices"));
    }
    kernels::runProbe(kernel, {argumentBuffer, sampleIndices ? &*sampleIndices : nullptr, results},
                      uint32_t(arguments.values.size()));
    const auto bytes = results.read();
    const auto* floats = reinterpret_cast<const float*>(bytes.data());
    return {floats, floats + bytes.size() / sizeof(float)};
}

std::vector<float> glProbe(const opengl::EglContext& context, const OpenGlForm& form, const ProbeArguments& arguments,
                           uint32_t resultsPerArgument) {
    const auto program = glpath::program(context, form);
    const auto values = std::as_bytes(std::span(arguments.values));
    const auto argumentBuffer = glpath::bindStorageBuffer(context, form, "Arguments", values.size(), values);
    const auto results = glpath::bindStorageBuffer(context, form, "Results", resultBytes(arguments, resultsPerArgument));
    std::optional<opengl::GlObject> sampleIndices;
    if (!arguments.sampleIndices.empty()) {
        const auto indices = std::as_bytes(std::span(arguments.sampleIndices));
        sampleIndices.emplace(glpath::bindStorageBuffer(context, form, "SampleIndices", indices.size(), indices));
    }
    const kernels::ProbeParameters parameters{uint32_t(arguments.values.size())};
    const auto parameterBuffer = glpath::bindParameters(context, form, parameters.members());
    glpath::dispatch(context, program, form, {parameters.argumentCount, 1, 1});
    return glpath::readBuffer(context, results, resultBytes(arguments, resultsPerArgument) / sizeof(float));
}

template <typename T>
std::vector<T> pbrProbeReference(const ProbeArguments& arguments) {
    using namespace reference;
    std::vector<T> results;
    results.reserve(arguments.values.size() * kPbrProbeResults * 4);
    for (size_t i = 0; i < arguments.values.size(); ++i) {
        const auto argument = glm::vec<4, T>(arguments.values[i]);
        const T c = argument.x, roughness = argument.y;
        const auto fresnel = FresnelSchlick(argument.w, vec3<T>(T(0.04f), T(0.5f), T(1)));
        const auto sample = ImportanceSampleGGX(vec2<T>(argument.z, argument.w), probeNormal<T>(i), roughness);
        const auto xi = Hammersley<T>(arguments.sampleIndices[i].x, arguments.sampleIndices[i].y);
        const auto lut = IntegrateBRDF(c, roughness, kDocumentSamples);
        results.insert(results.end(), {DistributionGGX(c, roughness), GeometrySmithForIBL(argument.z, c, roughness),
                                       GeometrySchlickGGXForIBL(c, roughness), T(0), fresnel.x, fresnel.y, fresnel.z, T(0),
                                       sample.x, sample.y, sample.z, T(0), xi.x, xi.y, lut.x, lut.y});
    }
    return results;
}

template <typename T>
std::vector<T> lutProbeReference(const ProbeArguments& arguments) {
    std::vector<T> results;
    results.reserve(arguments.values.size() * kLutProbeResults * 4);
    for (const auto& value : arguments.values) {
        const auto argument = glm::vec<4, T>(value);
        const auto lut = reference::IntegrateBrdfQuadrature(argument.x, argument.z, argument.y, kQuadratureNodes);
        results.insert(results.end(), {lut.x, lut.y, T(0), T(0)});
    }
    return results;
}

template std::vector<float> pbrProbeReference<float>(const ProbeArguments&);
template std::vector<double> pbrProbeReference<double>(const ProbeArguments&);
template std::vector<float> lutProbeReference<float>(const ProbeArguments&);
template std::vector<double> lutProbeReference<double>(const ProbeArguments&);

} // namespace iblkit::consistency
