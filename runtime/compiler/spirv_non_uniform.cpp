#include "spirv_non_uniform.hpp"

#include "spirv_module.hpp"

#include <spirv/unified1/spirv.hpp>

#include <map>
#include <set>

namespace iblkit::compiler {
namespace {

// The capability that lets an array of `element` be indexed non-uniformly, or 0.
uint32_t nonUniformCapabilityFor(const SpirvModule& module, uint32_t element, uint32_t storageClass) {
    const auto* type = module.definition(element);
    if (!type) return 0;
    if (type->opcode == spv::OpTypeSampledImage || type->opcode == spv::OpTypeSampler)
        return spv::CapabilitySampledImageArrayNonUniformIndexing;
    if (type->opcode == spv::OpTypeImage) {
        const bool buffer = type->operands[2] == spv::DimBuffer, storage = type->operands[kImageSampled] == 2;
        if (buffer) return storage ? spv::CapabilityStorageTexelBufferArrayNonUniformIndexing
                                   : spv::CapabilityUniformTexelBufferArrayNonUniformIndexing;
        return storage ? spv::CapabilityStorageImageArrayNonUniformIndexing : spv::CapabilitySampledImageArrayNonUniformIndexing;
    }
    if (type->opcode == spv::OpTypeStruct)
        return storageClass == spv::StorageClassStorageBuffer ? spv::CapabilityStorageBufferArrayNonUniformIndexing
                                                              : spv::CapabilityUniformBufferArrayNonUniformIndexing;
    return 0;
}

bool isConstant(const SpirvModule& module, uint32_t id) {
    const auto* definition = module.definition(id);
    return definition && (definition->opcode == spv::OpConstant || definition->opcode == spv::OpSpecConstant);
}

} // namespace

bool decorateNonUniformResourceIndexing(SpirvModule& module) {
    // Variables that are arrays of resources, with the capability their indexing needs.
    std::map<uint32_t, uint32_t> arrays; // variable -> capability
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        if (instruction.opcode != spv::OpVariable) continue;
        const uint32_t storageClass = instruction.operands[2];
        if (storageClass != spv::StorageClassUniformConstant && storageClass != spv::StorageClassStorageBuffer &&
            storageClass != spv::StorageClassUniform)
            continue;
        const auto* array = module.definition(module.pointeeOf(instruction.operands[0]));
        if (!array || (array->opcode != spv::OpTypeArray && array->opcode != spv::OpTypeRuntimeArray)) continue;
        if (const uint32_t capability = nonUniformCapabilityFor(module, array->operands[1], storageClass))
            arrays[instruction.operands[1]] = capability;
    }
    std::set<uint32_t> nonUniform, capabilities;
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        const auto op = instruction.opcode;
        if ((op == spv::OpAccessChain || op == spv::OpInBoundsAccessChain) && instruction.operands.size() > 3) {
            const auto found = arrays.find(instruction.operands[2]);
            if (found == arrays.end() || isConstant(module, instruction.operands[3])) continue;
            nonUniform.insert({instruction.operands[1], instruction.operands[3]});
            capabilities.insert(found->second);
        } else if (op == spv::OpLoad && nonUniform.count(instruction.operands[2])) {
            nonUniform.insert(instruction.operands[1]);
        } else if ((op == spv::OpSampledImage || op == spv::OpImage) && nonUniform.count(instruction.operands[2])) {
            nonUniform.insert(instruction.operands[1]);
        }
    }
    if (nonUniform.empty()) return false;
    for (const uint32_t id : nonUniform)
        module.insertBefore(module.afterLastAnnotation(), {spv::OpDecorate, {id, spv::DecorationNonUniform}});
    module.requireCapability(spv::CapabilityShaderNonUniform);
    for (const uint32_t capability : capabilities) module.requireCapability(capability);
    module.requireExtension("SPV_EXT_descriptor_indexing");
    return true;
}

} // namespace iblkit::compiler
