#include "spirv_image_access.hpp"

#include "spirv_module.hpp"

#include <spirv/unified1/spirv.hpp>

#include <set>

namespace iblkit::compiler {
namespace {

struct Access {
    bool read = false, written = false;
};

// How the shader uses the variable: through its loads (OpImageRead, OpImageWrite) or through
// texel pointers (atomics, which both read and write).
Access accessOf(SpirvModule& module, uint32_t variable) {
    const auto loads = module.loadsOf(variable);
    const std::set<uint32_t> images(loads.begin(), loads.end());
    Access access;
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        if (instruction.opcode == spv::OpImageRead && images.contains(instruction.operands[2])) access.read = true;
        if (instruction.opcode == spv::OpImageWrite && images.contains(instruction.operands[0])) access.written = true;
        if (instruction.opcode == spv::OpImageTexelPointer && instruction.operands[2] == variable)
            access.read = access.written = true;
    }
    return access;
}

size_t afterLastAnnotation(SpirvModule& module) {
    size_t after = 0;
    for (size_t i = 0; i < module.size(); ++i) {
        const uint32_t opcode = module.instruction(i).opcode;
        if (opcode == spv::OpDecorate || opcode == spv::OpMemberDecorate || opcode == spv::OpName ||
            opcode == spv::OpMemberName || opcode == spv::OpDecorateString)
            after = i + 1;
    }
    return after;
}

} // namespace

bool decorateStorageImageAccess(SpirvModule& module) {
    std::vector<std::pair<uint32_t, uint32_t>> decorations; // variable, decoration
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        if (instruction.opcode != spv::OpVariable || !module.storageImageTypeOf(instruction.operands[1])) continue;
        const uint32_t variable = instruction.operands[1];
        const Access access = accessOf(module, variable);
        if (access.read && !access.written) decorations.emplace_back(variable, spv::DecorationNonWritable);
        if (access.written && !access.read) decorations.emplace_back(variable, spv::DecorationNonReadable);
    }
    for (const auto& [variable, decoration] : decorations)
        module.insertBefore(afterLastAnnotation(module), {spv::OpDecorate, {variable, decoration}});
    return !decorations.empty();
}

} // namespace iblkit::compiler
