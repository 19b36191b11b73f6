#include "spirv_image_access.hpp"

#include "spirv_module.hpp"

#include <spirv/unified1/spirv.hpp>

#include <set>

namespace iblkit::compiler {
namespace {

struct Access {
    bool read = false, written = false;
};

// The variable and, for an array of images, every element pointer taken from it.
std::set<uint32_t> imagePointers(SpirvModule& module, uint32_t variable) {
    std::set<uint32_t> pointers{variable};
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        if ((instruction.opcode == spv::OpAccessChain || instruction.opcode == spv::OpInBoundsAccessChain) &&
            instruction.operands[2] == variable)
            pointers.insert(instruction.operands[1]);
    }
    return pointers;
}

// How the shader uses the variable: through its loads (OpImageRead, OpImageWrite) or through
// texel pointers (atomics, which both read and write).
Access accessOf(SpirvModule& module, uint32_t variable) {
    const auto pointers = imagePointers(module, variable);
    std::set<uint32_t> images;
    for (uint32_t pointer : pointers)
        for (uint32_t load : module.loadsOf(pointer)) images.insert(load);
    Access access;
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        if (instruction.opcode == spv::OpImageRead && images.contains(instruction.operands[2])) access.read = true;
        if (instruction.opcode == spv::OpImageWrite && images.contains(instruction.operands[0])) access.written = true;
        if (instruction.opcode == spv::OpImageTexelPointer && pointers.contains(instruction.operands[2]))
            access.read = access.written = true;
    }
    return access;
}

// A storage image variable, or an array of them (RWTexture2D<float4> mips[13]).
bool isStorageImageOrArray(SpirvModule& module, uint32_t variable) {
    if (module.storageImageTypeOf(variable)) return true;
    const auto* declaration = module.definition(variable);
    if (!declaration || declaration->opcode != spv::OpVariable) return false;
    const auto* array = module.definition(module.pointeeOf(declaration->operands[0]));
    if (!array || (array->opcode != spv::OpTypeArray && array->opcode != spv::OpTypeRuntimeArray)) return false;
    const auto* image = module.definition(array->operands[1]);
    return image && image->opcode == spv::OpTypeImage && image->operands[kImageSampled] == 2;
}

} // namespace

bool decorateStorageImageAccess(SpirvModule& module) {
    std::vector<std::pair<uint32_t, uint32_t>> decorations; // variable, decoration
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        if (instruction.opcode != spv::OpVariable || !isStorageImageOrArray(module, instruction.operands[1])) continue;
        const uint32_t variable = instruction.operands[1];
        const Access access = accessOf(module, variable);
        if (access.read && !access.written) decorations.emplace_back(variable, spv::DecorationNonWritable);
        if (access.written && !access.read) decorations.emplace_back(variable, spv::DecorationNonReadable);
    }
    for (const auto& [variable, decoration] : decorations)
        module.insertBefore(module.afterLastAnnotation(), {spv::OpDecorate, {variable, decoration}});
    return !decorations.empty();
}

} // namespace iblkit::compiler
