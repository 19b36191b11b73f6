#include "spirv_wave_prefix.hpp"

#include "spirv_module.hpp"

#include <spirv/unified1/spirv.hpp>

namespace iblkit::compiler {
namespace {

// The group operation is the fourth operand (after result type, result and scope) of the
// arithmetic, bitwise and logical group instructions and of OpGroupNonUniformBallotBitCount.
constexpr size_t kGroupOperation = 3;

bool takesAGroupOperation(uint32_t opcode) {
    return opcode == spv::OpGroupNonUniformBallotBitCount ||
           (opcode >= spv::OpGroupNonUniformIAdd && opcode <= spv::OpGroupNonUniformLogicalXor);
}

} // namespace

bool makeWavePrefixScansExclusive(SpirvModule& module) {
    bool changed = false;
    for (size_t i = 0; i < module.size(); ++i) {
        auto& instruction = module.instruction(i);
        if (takesAGroupOperation(instruction.opcode) && instruction.operands.size() > kGroupOperation &&
            instruction.operands[kGroupOperation] == spv::GroupOperationInclusiveScan) {
            instruction.operands[kGroupOperation] = spv::GroupOperationExclusiveScan;
            changed = true;
        }
    }
    return changed;
}

} // namespace iblkit::compiler
