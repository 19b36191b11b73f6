#include "spirv_operand_repairs.hpp"

#include "spirv_module.hpp"

#include <spirv/unified1/spirv.hpp>

#include <optional>

namespace iblkit::compiler {
namespace {

bool isBooleanType(const SpirvModule& module, uint32_t type) {
    const auto* declaration = module.definition(type);
    if (!declaration) return false;
    if (declaration->opcode == spv::OpTypeBool) return true;
    return declaration->opcode == spv::OpTypeVector && isBooleanType(module, declaration->operands[1]);
}

std::optional<uint32_t> logicalOpcodeFor(uint32_t opcode) {
    switch (opcode) {
    case spv::OpBitwiseOr: return spv::OpLogicalOr;
    case spv::OpBitwiseAnd: return spv::OpLogicalAnd;
    case spv::OpBitwiseXor: return spv::OpLogicalNotEqual;
    case spv::OpNot: return spv::OpLogicalNot;
    default: return std::nullopt;
    }
}

// Where an image instruction's operand mask is, counted in operands after the opcode word.
std::optional<size_t> imageOperandMaskAt(uint32_t opcode) {
    switch (opcode) {
    case spv::OpImageWrite: return 3;
    case spv::OpImageSampleImplicitLod:
    case spv::OpImageSampleExplicitLod:
    case spv::OpImageSampleProjImplicitLod:
    case spv::OpImageSampleProjExplicitLod:
    case spv::OpImageFetch:
    case spv::OpImageRead:
    case spv::OpImageSparseSampleImplicitLod:
    case spv::OpImageSparseSampleExplicitLod:
    case spv::OpImageSparseFetch:
    case spv::OpImageSparseRead: return 4;
    case spv::OpImageSampleDrefImplicitLod:
    case spv::OpImageSampleDrefExplicitLod:
    case spv::OpImageSampleProjDrefImplicitLod:
    case spv::OpImageSampleProjDrefExplicitLod:
    case spv::OpImageGather:
    case spv::OpImageDrefGather:
    case spv::OpImageSparseSampleDrefImplicitLod:
    case spv::OpImageSparseSampleDrefExplicitLod:
    case spv::OpImageSparseGather:
    case spv::OpImageSparseDrefGather: return 5;
    default: return std::nullopt;
    }
}

bool isFixedConstant(const SpirvModule& module, uint32_t id) {
    const auto* definition = module.definition(id);
    if (!definition) return false;
    const auto opcode = definition->opcode;
    return opcode == spv::OpConstant || opcode == spv::OpConstantComposite || opcode == spv::OpConstantNull;
}

// The operand that follows the mask for the Offset bit: the operands of the lower bits come
// first, Grad's two of them.
size_t offsetOperandAt(size_t maskAt, uint32_t mask) {
    size_t at = maskAt + 1;
    if (mask & spv::ImageOperandsBiasMask) ++at;
    if (mask & spv::ImageOperandsLodMask) ++at;
    if (mask & spv::ImageOperandsGradMask) at += 2;
    if (mask & spv::ImageOperandsConstOffsetMask) ++at;
    return at;
}

bool isGather(uint32_t opcode) {
    return opcode == spv::OpImageGather || opcode == spv::OpImageDrefGather || opcode == spv::OpImageSparseGather ||
           opcode == spv::OpImageSparseDrefGather;
}

// Offset on any image operation, or ConstOffset(s) on a gather, need ImageGatherExtended.
bool needsGatherExtended(SpirvModule& module) {
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        const auto maskAt = imageOperandMaskAt(instruction.opcode);
        if (!maskAt || instruction.operands.size() <= *maskAt) continue;
        const uint32_t mask = instruction.operands[*maskAt];
        if (mask & spv::ImageOperandsOffsetMask) return true;
        if (isGather(instruction.opcode) && (mask & (spv::ImageOperandsConstOffsetMask | spv::ImageOperandsConstOffsetsMask))) return true;
    }
    return false;
}

} // namespace

bool logicalOperationsOnBooleans(SpirvModule& module) {
    bool changed = false;
    for (size_t i = 0; i < module.size(); ++i) {
        auto& instruction = module.instruction(i);
        const auto logical = logicalOpcodeFor(instruction.opcode);
        if (!logical || instruction.operands.empty() || !isBooleanType(module, instruction.operands[0])) continue;
        instruction.opcode = *logical;
        changed = true;
    }
    return changed;
}

bool constantImageOffsets(SpirvModule& module) {
    bool changed = false;
    for (size_t i = 0; i < module.size(); ++i) {
        auto& instruction = module.instruction(i);
        const auto maskAt = imageOperandMaskAt(instruction.opcode);
        if (!maskAt || instruction.operands.size() <= *maskAt) continue;
        const uint32_t mask = instruction.operands[*maskAt];
        if (!(mask & spv::ImageOperandsOffsetMask) || (mask & spv::ImageOperandsConstOffsetMask)) continue;
        const size_t offsetAt = offsetOperandAt(*maskAt, mask);
        if (offsetAt >= instruction.operands.size() || !isFixedConstant(module, instruction.operands[offsetAt])) continue;
        // ConstOffset's bit sits just below Offset's, so the offset keeps its place among the operands.
        instruction.operands[*maskAt] = (mask & ~spv::ImageOperandsOffsetMask) | spv::ImageOperandsConstOffsetMask;
        changed = true;
    }
    if (!needsGatherExtended(module)) changed |= module.dropCapability(spv::CapabilityImageGatherExtended);
    return changed;
}

} // namespace iblkit::compiler
