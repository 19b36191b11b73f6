#include "spirv_glslang_repairs.hpp"

#include "spirv_module.hpp"

#include <spirv/unified1/spirv.hpp>

#include <optional>
#include <set>

namespace iblkit::compiler {
namespace {

// Operand positions (after the opcode word) of an atomic's value operands.
std::vector<size_t> atomicValueOperands(uint32_t opcode) {
    switch (opcode) {
    case spv::OpAtomicExchange:
    case spv::OpAtomicIAdd:
    case spv::OpAtomicISub:
    case spv::OpAtomicSMin:
    case spv::OpAtomicUMin:
    case spv::OpAtomicSMax:
    case spv::OpAtomicUMax:
    case spv::OpAtomicAnd:
    case spv::OpAtomicOr:
    case spv::OpAtomicXor: return {5};
    case spv::OpAtomicCompareExchange: return {6, 7};
    default: return {};
    }
}

std::optional<uint32_t> integerWidth(const SpirvModule& module, uint32_t type) {
    const auto* declaration = module.definition(type);
    if (!declaration || declaration->opcode != spv::OpTypeInt) return std::nullopt;
    return declaration->operands[1];
}

// `value` as a `type` of the same width: a constant of that type, or a bitcast written before
// the instruction at `at` (whose index it shifts by one).
uint32_t reinterpreted(SpirvModule& module, uint32_t value, uint32_t type, size_t& at) {
    if (const auto* constant = module.definition(value); constant && constant->opcode == spv::OpConstant) {
        SpirvInstruction same{spv::OpConstant, constant->operands};
        same.operands[0] = type;
        const size_t before = module.size();
        const uint32_t id = module.declareOnce(same);
        if (module.size() > before) ++at; // declared among the globals, before every function
        return id;
    }
    const uint32_t id = module.newId();
    module.insertBefore(at++, {spv::OpBitcast, {type, id, value}});
    return id;
}

bool isIntegerOrDouble(const SpirvModule& module, uint32_t type) {
    const auto* declaration = module.definition(type);
    if (!declaration) return false;
    if (declaration->opcode == spv::OpTypeInt) return true;
    if (declaration->opcode == spv::OpTypeFloat) return declaration->operands[1] == 64;
    if (declaration->opcode == spv::OpTypeVector || declaration->opcode == spv::OpTypeArray)
        return isIntegerOrDouble(module, declaration->operands[1]);
    return false;
}


} // namespace

bool matchAtomicValueTypes(SpirvModule& module) {
    bool changed = false;
    for (size_t i = 0; i < module.size(); ++i) {
        const auto operands = atomicValueOperands(module.instruction(i).opcode);
        if (operands.empty()) continue;
        // The memory's type rules: the result and every value must be of it.
        const uint32_t memoryType = module.pointeeOf(module.typeOf(module.instruction(i).operands[2]));
        const auto width = integerWidth(module, memoryType);
        if (!width) continue;
        for (const size_t operand : operands) {
            const uint32_t value = module.instruction(i).operands[operand];
            const uint32_t valueType = module.typeOf(value);
            if (valueType == memoryType || integerWidth(module, valueType) != width) continue;
            module.instruction(i).operands[operand] = reinterpreted(module, value, memoryType, i);
            changed = true;
        }
        const uint32_t resultType = module.instruction(i).operands[0];
        if (resultType == memoryType || integerWidth(module, resultType) != width) continue;
        // The atomic returns the memory's type; the uses keep the type they read, through a bitcast.
        const uint32_t result = module.instruction(i).operands[1];
        const uint32_t memoryResult = module.newId();
        module.instruction(i).operands[0] = memoryType;
        module.instruction(i).operands[1] = memoryResult;
        module.insertBefore(i + 1, {spv::OpBitcast, {resultType, result, memoryResult}});
        ++i;
        changed = true;
    }
    return changed;
}

bool decorateFragmentIntegerInputsFlat(SpirvModule& module) {
    if (entryExecutionModel(module) != spv::ExecutionModelFragment) return false;
    std::set<uint32_t> flat;
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        if (instruction.opcode == spv::OpDecorate && instruction.operands[1] == spv::DecorationFlat)
            flat.insert(instruction.operands[0]);
    }
    std::vector<uint32_t> unflat;
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        if (instruction.opcode != spv::OpVariable || instruction.operands[2] != spv::StorageClassInput) continue;
        const uint32_t variable = instruction.operands[1];
        if (!flat.contains(variable) && isIntegerOrDouble(module, module.pointeeOf(instruction.operands[0])))
            unflat.push_back(variable);
    }
    for (const uint32_t variable : unflat)
        module.insertBefore(module.afterLastAnnotation(), {spv::OpDecorate, {variable, spv::DecorationFlat}});
    return !unflat.empty();
}

} // namespace iblkit::compiler
