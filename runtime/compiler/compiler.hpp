#pragma once

#include "compile_options.hpp"
#include "cross_compile.hpp"
#include "reflection.hpp"

#include <cstdint>
#include <map>
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
};

// HLSL -> validated SPIR-V and its reflection. Throws CompileError.
CompiledShader compileShader(const CompileOptions& options);

CrossCompiled crossCompileShader(const CompiledShader& shader, CrossTarget target);

// The reflection JSON: resources, workgroup size, constants, the binding rule, and where each
// resource lands in every target of `targets`.
std::string reflectionJson(const CompiledShader& shader, const std::map<CrossTarget, CrossCompiled>& targets);

// A Makefile rule "target: source includes..." for Ninja's and Make's depfile support.
std::string makeDepfile(const std::string& target, const CompiledShader& shader);

} // namespace iblkit::compiler
