#pragma once

namespace iblkit::compiler {

class SpirvModule;

// Repairs of SPIR-V that glslang's HLSL frontend writes invalid, applied before legalization
// (whose validation would refuse it). Each returns whether it changed the module.

// An atomic on a RWByteAddressBuffer given int literals (`InterlockedAdd(0, 1, previous)`,
// `InterlockedCompareExchange(8, 0, 7, original)`) keeps their int type for the value, and for
// the result too, on uint memory; SPIR-V requires both to be the memory's type. Values are
// reinterpreted as it (OpBitcast, or the constant with the same bits) and the result is read
// back through a bitcast: HLSL's own int/uint conversion.
bool matchAtomicValueTypes(SpirvModule& module);

// Vulkan requires every integer or double input of a fragment shader to be Flat
// (VUID-StandaloneSpirv-Flat-04744); glslang leaves the decoration off built-ins such as
// WaveGetLaneIndex()'s SubgroupLocalInvocationId. HLSL never interpolates an integer.
bool decorateFragmentIntegerInputsFlat(SpirvModule& module);

} // namespace iblkit::compiler
