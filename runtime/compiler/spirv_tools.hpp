#pragma once

#include "compile_options.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::compiler {

// SPIRV-Tools, in the Vulkan 1.1 environment. Each throws CompileError naming sourceName.
// SPIRV-Tools' legalization recipe for SPIR-V from HLSL (as DXC and glslangValidator run it):
// inlines functions and removes the by-value copies of textures and samplers that HLSL
// parameters make, so each sampling names the global resources.
std::vector<uint32_t> legalizeHlslSpirv(const std::vector<uint32_t>& spirv, const std::string& sourceName);
enum class SpirvEnvironment { Vulkan11, OpenGl45 };
void validateSpirv(const std::vector<uint32_t>& spirv, const std::string& sourceName,
                   SpirvEnvironment environment = SpirvEnvironment::Vulkan11);
std::vector<uint32_t> optimizeSpirv(const std::vector<uint32_t>& spirv, OptimizationLevel level,
                                    const std::string& sourceName);
std::vector<uint32_t> stripDebugInfo(const std::vector<uint32_t>& spirv, const std::string& sourceName);
std::string disassembleSpirv(const std::vector<uint32_t>& spirv);

} // namespace iblkit::compiler
