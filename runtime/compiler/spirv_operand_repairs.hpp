#pragma once

namespace iblkit::compiler {

class SpirvModule;

// OpBitwiseOr, OpBitwiseAnd, OpBitwiseXor and OpNot on booleans (HLSL's `a | b` of two bools,
// which glslang writes as integer operations) become OpLogicalOr, OpLogicalAnd,
// OpLogicalNotEqual and OpLogicalNot: the same values, in the instructions SPIR-V allows for
// booleans. Returns whether it changed the module.
bool logicalOperationsOnBooleans(SpirvModule& module);

// An offset passed through a function parameter makes glslang declare ImageGatherExtended, the
// capability of run-time offsets; once legalized the offset is a constant (legalization makes
// it ConstOffset), and a device without shaderImageGatherExtended refuses the capability
// (VUID-VkShaderModuleCreateInfo-pCode-01091). An Offset whose value is a constant becomes
// ConstOffset, and the capability goes where no image operation needs it any more. Returns
// whether it changed the module.
bool constantImageOffsets(SpirvModule& module);

} // namespace iblkit::compiler
