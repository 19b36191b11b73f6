#pragma once

#include "shader_stage.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace spirv_cross {
class CompilerGLSL;
}

namespace iblkit::compiler {

// A GLSL-family form and what it needs of its reader.
struct ReadableGlsl {
    std::string source;
    uint32_t version = 0;
    std::vector<std::string> extensions; // beyond what SPIRV-Cross declares itself
};

// The form at the lowest language version, with the fewest extensions, that its own compiler
// (glslang, the reference compiler of GLSL and ESSL) reads back: GLSL 450; ESSL 3.10, then 3.20
// (cube map arrays, sampler arrays indexed at run time, gl_Layer and the geometry and
// tessellation built-ins), then 3.20 with each extension glslang names for what it lacks.
// A form no step makes readable is not written: CompileError names the form, what its reader
// could not take, and glslang's words on a second line.
ReadableGlsl readableGlsl(spirv_cross::CompilerGLSL& compiler, ShaderStage stage, bool es, bool vulkanSemantics,
                          const std::string& formName, const std::string& sourceName);

} // namespace iblkit::compiler
