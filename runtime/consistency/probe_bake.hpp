#pragma once

#include "gl_bake.hpp"
#include "shader_paths.hpp"
#include "context_options.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace iblkit::consistency {

// What a probe kernel (PbrProbeCS, LutProbeCS, BsdfProbeCS) evaluates: one argument per thread, and for
// PbrProbeCS the (i, n) of each argument's Hammersley point.
struct ProbeArguments {
    std::vector<glm::vec4> values;
    std::vector<glm::uvec2> sampleIndices; // one per value for PbrProbeCS; empty for LutProbeCS
};

// float4 results per argument (see the shaders' headers).
inline constexpr uint32_t kPbrProbeResults = 4;
inline constexpr uint32_t kLutProbeResults = 1;
inline constexpr uint32_t kBsdfProbeResults = 7;

// The probe's Results, resultsPerArgument float4 per argument, on a Vulkan path and on OpenGL.
std::vector<float> gpuProbe(const vulkan::VulkanContext& context, const PathProgram& program,
                            const ProbeArguments& arguments, uint32_t resultsPerArgument);
std::vector<float> glProbe(const opengl::EglContext& context, const OpenGlForm& form, const ProbeArguments& arguments,
                           uint32_t resultsPerArgument);

// The C++ twins of both probes (reference::pbr.hpp, reference::lut_quadrature.hpp): T = float
// follows the shaders' arithmetic, T = double is the ground truth; laid out as Results.
template <typename T>
std::vector<T> pbrProbeReference(const ProbeArguments& arguments);
template <typename T>
std::vector<T> lutProbeReference(const ProbeArguments& arguments);
// BsdfProbeCS's twin (reference::path_tracer_*.hpp), laid out as its Results.
template <typename T>
std::vector<T> bsdfProbeReference(const ProbeArguments& arguments);

} // namespace iblkit::consistency
