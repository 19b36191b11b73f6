#pragma once

#include "reflection.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace iblkit::bake {

// hlsl/ as it was when the program was built, by path ("hlsl/Common/PBR.fxh").
const std::map<std::string, std::string>& embeddedShaderFiles();

struct BakeShader {
    std::vector<uint32_t> spirv;
    compiler::ShaderReflection reflection;
};

// Compiles hlsl/<name>.hlsl from the built-in copy with the kit's compiler, with the given
// defines and storage image formats. Throws compiler::CompileError.
BakeShader compileBakeShader(const std::string& name, const std::map<std::string, std::string>& defines = {},
                             const std::map<std::string, std::string>& imageFormats = {});

} // namespace iblkit::bake
