#pragma once

#include "reflection.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::compiler {

// VulkanGlsl and VulkanEssl are GLSL 450 and ESSL 310 with Vulkan semantics (sets, bindings,
// separate textures and samplers kept, GL_KHR_shader_subgroup for wave operations): the forms
// that compile back to SPIR-V for Vulkan.
enum class CrossTarget { Glsl, Essl, Msl, Hlsl, VulkanGlsl, VulkanEssl };
inline constexpr CrossTarget kCrossTargets[] = {CrossTarget::Glsl, CrossTarget::Essl,       CrossTarget::Msl,
                                              CrossTarget::Hlsl, CrossTarget::VulkanGlsl, CrossTarget::VulkanEssl};
std::string_view crossTargetName(CrossTarget target);

// Where one HLSL resource lands in a target language.
struct TargetBinding {
    std::string resource;  // the HLSL name; for a combined sampler "Texture+Sampler"
    std::string namespace_; // "uniform_block", "texture_unit", "image_unit", "storage_buffer" (GL);
                            // "buffer", "texture", "sampler" (MSL); "b", "t", "s", "u" (HLSL)
    uint32_t slot;
    std::string declaredName; // the name in the generated source when it differs from resource
    std::string format;       // image units: the format declared in the target
    std::string adaptedFrom;  // ESSL: the original format when a stand-in was declared
};

struct CrossCompiled {
    std::string source;
    std::vector<TargetBinding> bindings;
    // GLSL and ESSL forms: the language version and the extensions beyond SPIRV-Cross's own that
    // the form needs to be read (ESSL 3.20 for a cube map array; 0 for MSL and HLSL).
    uint32_t version = 0;
    std::vector<std::string> extensions;
};

// SPIR-V -> GLSL 450 for OpenGL 4.5, ESSL 310 for OpenGL ES 3.1 (3.20, and extensions, where the
// shader needs them: readable_glsl.hpp), GLSL 450 and ESSL with Vulkan semantics, MSL (2.1; 2.2 with 64-bit integers) or HLSL (the lowest shader model from
// 5.0 to 6.2 that has what the module uses) with SPIRV-Cross. Resources are numbered per target
// namespace in register order (docs/bindings.md). Throws CompileError naming the form, the
// construct it cannot express and, where another form can, the option that writes that form.
CrossCompiled crossCompile(const std::vector<uint32_t>& spirv, const ShaderReflection& reflection, CrossTarget target,
                           const std::string& sourceName);

} // namespace iblkit::compiler
