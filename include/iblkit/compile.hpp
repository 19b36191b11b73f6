#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace iblkit {

// The forms beside SPIR-V that SPIRV-Cross writes. VulkanGlsl and VulkanEssl keep Vulkan's
// sets, bindings and separate samplers: the forms that compile back to SPIR-V for Vulkan.
enum class ShaderForm { Glsl, Essl, Msl, Hlsl, VulkanGlsl, VulkanEssl };

// "glsl", "essl", "msl", "hlsl", "vulkan-glsl", "vulkan-essl": as the command line's flags name them.
std::string_view shaderFormName(ShaderForm form);

enum class ShaderStage { Vertex, TessControl, TessEvaluation, Geometry, Fragment, Compute };

// glslang's short names (vert, tesc, tese, geom, frag, comp) and the long ones (vertex, pixel,
// hull, domain, ...); nothing for a name it does not know.
std::optional<ShaderStage> shaderStageNamed(std::string_view name);

enum class Optimization { None, Performance, Size };

// HLSL 2021 (DXC's default) is lowered to what glslang reads; 2018 is given to glslang as it is.
enum class HlslVersion { Hlsl2018, Hlsl2021 };

// The one rule from HLSL registers to Vulkan descriptors (docs/bindings.md): set = space,
// binding = shift of the register's class + register. Each class owns the bindings from its shift
// to the next class's, so that no two resources can share one.
struct BindingShifts {
    uint32_t constantBuffers = 0;  // b registers
    uint32_t shaderResources = 32; // t
    uint32_t samplers = 64;        // s
    uint32_t unorderedAccess = 96; // u
};

struct CompileRequest {
    std::filesystem::path source; // the HLSL file; its folder is searched first for #include
    // Compiled instead of the file's contents when set; `source` still names it in messages.
    std::optional<std::string> sourceText;
    std::string entryPoint = "main";
    std::optional<ShaderStage> stage; // empty: read from the entry point's attributes ([numthreads] ...)
    std::vector<std::filesystem::path> includeDirs;
    std::map<std::string, std::string> defines;      // NAME -> VALUE ("" for a bare NAME)
    std::map<std::string, std::string> imageFormats; // storage image formats by resource name, "rg16f", "rgba8", ...
    BindingShifts bindingShifts;
    Optimization optimization = Optimization::None;
    bool stripDebugInfo = false; // of the SPIR-V only: the other forms keep the names
    HlslVersion hlslVersion = HlslVersion::Hlsl2021;
    bool enable16BitTypes = false; // DXC's -enable-16bit-types: half and min16* are 16 bits wide
    // The forms to write beside SPIR-V: every one unless told otherwise.
    std::set<ShaderForm> forms = {ShaderForm::Glsl, ShaderForm::Essl,       ShaderForm::Msl,
                                  ShaderForm::Hlsl, ShaderForm::VulkanGlsl, ShaderForm::VulkanEssl};
    // The path a depfile names as its target (where the caller writes the SPIR-V); empty: no depfile.
    std::string depfileTarget;
    // Preprocess in a child process under time and memory limits, so that a source whose macros
    // expand without bound is an error rather than a hang: for sources you do not trust (the
    // command line does it). It forks the calling process.
    bool boundPreprocessing = false;
};

struct CompileResult {
    std::vector<uint32_t> spirv; // validated; optimized and stripped as asked
    std::map<ShaderForm, std::string> forms;   // the source of each form produced
    // A form that cannot express the shader (wave operations in OpenGL GLSL, ...) is refused
    // with its one-line reason, and does not stop the others.
    std::map<ShaderForm, std::string> refusedForms;
    // Resources by name with their bindings in every produced form, the workgroup size, the
    // constants, and why each refused form was refused (docs/compiler.md).
    std::string reflectionJson;
    std::string depfile; // "target: source includes...", when depfileTarget was given
    std::vector<std::filesystem::path> includedFiles;
    std::vector<std::string> warnings; // the compiler's, one a line
};

// HLSL to SPIR-V and the forms asked for. Throws Error: CompileFailed for the shader's errors,
// BadInput for a request out of range (a binding shift past 65534).
CompileResult compileShader(const CompileRequest& request);

} // namespace iblkit
