#pragma once

#include "compile_options.hpp"
#include "register_binding.hpp"
#include "shader_stage.hpp"

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace iblkit::compiler {

struct FrontendResult {
    std::vector<uint32_t> spirv;
    ShaderStage stage;
    std::vector<ResourceRegister> registers; // in declaration order
    std::vector<std::string> includedFiles;  // every file #included, directly or not
    std::vector<std::string> warnings;
    std::map<std::string, std::string> imageFormats; // from [[vk::image_format]], by resource name
    std::vector<std::string> kitEdits;               // what the lowering changed (lowering.hpp)
    BindingShifts bindingShifts;                     // the options', or the defaults grown to fit
    std::set<std::string> packedMembers;             // cbuffer members placed by packoffset
};

// HLSL -> SPIR-V (Vulkan 1.1, SPIR-V 1.3) with glslang's HLSL frontend: the preprocessor
// with the options' defines and include folders, the stage deduced or given, the kit's
// register rule. Throws CompileError.
FrontendResult compileHlsl(const CompileOptions& options);

// The source text as glslang reads it (the file's own bytes), or CompileError.
std::string readSource(const std::filesystem::path& path);

} // namespace iblkit::compiler
