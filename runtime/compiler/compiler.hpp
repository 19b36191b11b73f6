#pragma once

#include "compile_options.hpp"
#include "cross_compile.hpp"
#include "reflection.hpp"

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace iblkit::compiler {

struct CompiledShader {
    std::string sourceName;
    std::vector<uint32_t> spirv;      // validated; optimized and stripped as asked
    std::vector<uint32_t> namedSpirv; // validated and optimized, names kept: what the other forms come from
    ShaderReflection reflection;
    BindingShifts bindingShifts;
    std::vector<std::string> includedFiles;
    std::vector<std::string> warnings;
    // What the kit rewrote for glslang or for Vulkan, by id (kit_edits.hpp): empty when glslang's
    // own output was enough.
    std::vector<std::string> kitEdits;
};

// HLSL -> validated SPIR-V and its reflection. Throws CompileError.
CompiledShader compileShader(const CompileOptions& options);

CrossCompiled crossCompileShader(const CompiledShader& shader, CrossTarget target);

// Each form asked for, produced or refused: a form that cannot express the shader (wave
// operations in OpenGL GLSL, an image ESSL cannot read and write) does not stop the others.
struct ShaderForms {
    std::map<CrossTarget, CrossCompiled> produced;
    std::map<CrossTarget, std::string> refused; // the one-line reason (CompileError's message)
};
ShaderForms crossCompileForms(const CompiledShader& shader, const std::set<CrossTarget>& targets);

// The reflection JSON: resources, workgroup size, constants, the binding rule, where each
// resource lands in every produced form, and why each refused form was refused.
std::string reflectionJson(const CompiledShader& shader, const std::map<CrossTarget, CrossCompiled>& targets,
                           const std::map<CrossTarget, std::string>& refused = {});

// A Makefile rule "target: source includes..." for Ninja's and Make's depfile support.
std::string makeDepfile(const std::string& target, const CompiledShader& shader);

} // namespace iblkit::compiler
