#pragma once

#include <string>

namespace iblkit::compiler {

// SPIRV-Cross writes a float matrix loaded from a byte-address buffer as
// `asfloat(uint4x4(B.Load(0), ...))`: an integer matrix, which no SPIR-V compiler of HLSL
// (glslang, or DXC for Vulkan) can type. The same load is written here as
// `float4x4(asfloat(B.Load(0)), ...)`, component for component, so the HLSL form compiles back.
std::string withFloatMatrixLoads(std::string source);

} // namespace iblkit::compiler
