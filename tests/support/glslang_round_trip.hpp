#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::testing {

// Compiles a generated GLSL 450 or ESSL 310 compute shader back to SPIR-V with glslang's GLSL
// frontend for OpenGL (ARB_gl_spirv) and validates it with SPIRV-Tools. Returns "" on success,
// otherwise glslang's or the validator's messages.
std::string compileGlslBack(const std::string& source);

} // namespace iblkit::testing
