#include "spirv_cbuffer_layout.hpp"

#include "compile_error.hpp"
#include "spirv_module.hpp"

#include <spirv/unified1/spirv.hpp>

#include <map>
#include <optional>
#include <set>

namespace iblkit::compiler {
namespace {

constexpr uint32_t kRegister = 16; // bytes in one of Direct3D's constant registers

uint32_t roundUp(uint32_t value, uint32_t to) { return (value + to - 1) / to * to; }


class Packing {
public:
    Packing(const SpirvModule& module, const std::set<std::string>& packedMembers) : module_(module), packed_(packedMembers) {
        for (size_t i = 0; i < module.size(); ++i) {
            const auto& instruction = module.instruction(i);
            if (instruction.opcode == spv::OpName) names_[instruction.operands[0]] = literalString(instruction.operands, 1);
            if (instruction.opcode == spv::OpMemberName)
                memberNames_[{instruction.operands[0], instruction.operands[1]}] = literalString(instruction.operands, 2);
            if (instruction.opcode == spv::OpMemberDecorate) {
                const std::pair member{instruction.operands[0], instruction.operands[1]};
                if (instruction.operands[2] == spv::DecorationOffset) offsets_[member] = instruction.operands[3];
                if (instruction.operands[2] == spv::DecorationRowMajor) rowMajor_.insert(member);
            }
            if (instruction.opcode == spv::OpDecorate && instruction.operands[1] == spv::DecorationBlock) blocks_.insert(instruction.operands[0]);
        }
    }

    bool isBlock(uint32_t type) const { return blocks_.contains(type); }
    std::string nameOf(uint32_t id) const { return names_.contains(id) ? names_.at(id) : "#" + std::to_string(id); }

    // The first member of `structType` (or of a struct inside it) whose HLSL offset differs from
    // the SPIR-V's: its path and both offsets.
    struct Difference {
        std::string member;
        uint32_t hlsl = 0, spirv = 0;
    };
    // Each member is placed after the one before it as the SPIR-V has that one (an explicit
    // packoffset moves both alike); only a member HLSL packs inside the padded end of an array,
    // struct or matrix before it is one Vulkan cannot hold.
    std::optional<Difference> firstDifference(uint32_t structType, int depth = 0) const {
        const auto* declaration = module_.definition(structType);
        if (!declaration || declaration->opcode != spv::OpTypeStruct || depth > 16) return std::nullopt;
        std::optional<std::pair<uint32_t, uint32_t>> previous; // its offset and its HLSL size
        for (uint32_t m = 0; m + 1 < declaration->operands.size(); ++m) {
            const uint32_t type = declaration->operands[m + 1];
            const bool rowMajor = rowMajor_.contains({structType, m});
            const auto spirv = offsets_.find({structType, m});
            if (spirv == offsets_.end()) return std::nullopt;
            const std::string member = memberName(structType, m);
            if (previous) {
                const uint32_t packed = placed(previous->first + previous->second, type, rowMajor);
                const bool insidePadding = packed < previous->first + roundUp(previous->second, kRegister);
                const bool afterRegisterStarter = startsRegister(declaration->operands[m]);
                if (afterRegisterStarter && insidePadding && spirv->second != packed && !packed_.contains(member))
                    return Difference{member, packed, spirv->second};
            }
            if (auto inner = firstDifference(elementStruct(type), depth + 1)) {
                inner->member = member + "." + inner->member;
                return inner;
            }
            previous = std::make_pair(spirv->second, sizeOf(type, rowMajor));
        }
        return std::nullopt;
    }

private:
    std::string memberName(uint32_t structType, uint32_t member) const {
        const auto found = memberNames_.find({structType, member});
        return found != memberNames_.end() ? found->second : "member " + std::to_string(member);
    }

    uint32_t elementStruct(uint32_t type) const {
        const auto* declaration = module_.definition(type);
        while (declaration && declaration->opcode == spv::OpTypeArray) declaration = module_.definition(declaration->operands[1]);
        return declaration && declaration->opcode == spv::OpTypeStruct ? declaration->operands[0] : 0;
    }

    uint32_t scalarBytes(uint32_t type) const {
        const auto* declaration = module_.definition(type);
        if (!declaration) return 4;
        if (declaration->opcode == spv::OpTypeVector || declaration->opcode == spv::OpTypeMatrix) return scalarBytes(declaration->operands[1]);
        if (declaration->opcode == spv::OpTypeFloat || declaration->opcode == spv::OpTypeInt) return declaration->operands[1] / 8;
        return 4; // bool
    }

    // Whether a member of this type starts a register of its own: arrays, structs and matrices.
    bool startsRegister(uint32_t type) const {
        const auto* declaration = module_.definition(type);
        return declaration && (declaration->opcode == spv::OpTypeArray || declaration->opcode == spv::OpTypeStruct ||
                               declaration->opcode == spv::OpTypeMatrix);
    }

    // Where a member of `type` goes after bytes [0, end): at a register's start if it must, or
    // if it would cross one.
    uint32_t placed(uint32_t end, uint32_t type, bool rowMajor) const {
        if (startsRegister(type)) return roundUp(end, kRegister);
        const uint32_t size = sizeOf(type, rowMajor);
        const uint32_t aligned = roundUp(end, scalarBytes(type));
        return aligned / kRegister != (aligned + size - 1) / kRegister ? roundUp(aligned, kRegister) : aligned;
    }

    // The bytes a member of `type` covers, its last register only as far as it fills it.
    uint32_t sizeOf(uint32_t type, bool rowMajor) const {
        const auto* declaration = module_.definition(type);
        if (!declaration) return 4;
        switch (declaration->opcode) {
        case spv::OpTypeVector: return declaration->operands[2] * scalarBytes(declaration->operands[1]);
        case spv::OpTypeMatrix: {
            const auto* column = module_.definition(declaration->operands[1]);
            const uint32_t rows = column ? column->operands[2] : 4, columns = declaration->operands[2];
            const uint32_t registers = rowMajor ? rows : columns, perRegister = rowMajor ? columns : rows;
            return (registers - 1) * kRegister + perRegister * scalarBytes(type);
        }
        case spv::OpTypeArray: {
            const auto* length = module_.definition(declaration->operands[2]);
            const uint32_t count = length ? length->operands[2] : 1;
            const uint32_t element = sizeOf(declaration->operands[1], rowMajor);
            return (count - 1) * roundUp(element, kRegister) + element;
        }
        case spv::OpTypeStruct: {
            uint32_t end = 0;
            for (uint32_t m = 0; m + 1 < declaration->operands.size(); ++m) {
                const uint32_t member = declaration->operands[m + 1];
                const bool memberRowMajor = rowMajor_.contains({declaration->operands[0], m});
                end = placed(end, member, memberRowMajor) + sizeOf(member, memberRowMajor);
            }
            return end;
        }
        default: return scalarBytes(type);
        }
    }

    const SpirvModule& module_;
    const std::set<std::string>& packed_;
    std::map<uint32_t, std::string> names_;
    std::map<std::pair<uint32_t, uint32_t>, std::string> memberNames_;
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> offsets_;
    std::set<std::pair<uint32_t, uint32_t>> rowMajor_;
    std::set<uint32_t> blocks_;
};

} // namespace

void refuseUnportableConstantBufferPacking(const SpirvModule& module, const std::set<std::string>& packedMembers,
                                           const std::string& sourceName) {
    const Packing packing(module, packedMembers);
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        if (instruction.opcode != spv::OpVariable || instruction.operands[2] != spv::StorageClassUniform) continue;
        uint32_t block = module.pointeeOf(instruction.operands[0]);
        if (const auto* array = module.definition(block); array && array->opcode == spv::OpTypeArray) block = array->operands[1];
        if (!packing.isBlock(block)) continue;
        if (const auto difference = packing.firstDifference(block))
            throw CompileError(sourceName + ": error: constant buffer '" + packing.nameOf(block) + "', member '" +
                               difference->member + "': Direct3D packs it at byte " + std::to_string(difference->hlsl) +
                               ", into the last register of the array, struct or matrix before it, where a Vulkan uniform "
                               "block cannot place it (the SPIR-V has it at byte " + std::to_string(difference->spirv) +
                               "), so the application's constant data would be read at the wrong place: start it on a "
                               "register of its own (pad the member before it to a float4) or move it before that member");
    }
}

} // namespace iblkit::compiler
