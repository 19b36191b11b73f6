#define SPV_ENABLE_UTILITY_CODE
#include "spirv_module.hpp"

#include <spirv/unified1/spirv.hpp>

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace iblkit::compiler {
namespace {

constexpr size_t kHeaderWords = 5;
constexpr size_t kIdBoundWord = 3;

// The result id's operand index, or -1 when the instruction has none.
int resultIndex(uint32_t opcode) {
    bool hasResult = false, hasResultType = false;
    spv::HasResultAndType(static_cast<spv::Op>(opcode), &hasResult, &hasResultType);
    if (!hasResult) return -1;
    return hasResultType ? 1 : 0;
}

bool isNameOrDecoration(uint32_t opcode) {
    return opcode == spv::OpName || opcode == spv::OpMemberName || opcode == spv::OpDecorate ||
           opcode == spv::OpMemberDecorate || opcode == spv::OpString || opcode == spv::OpSource ||
           opcode == spv::OpLine || opcode == spv::OpDecorateString || opcode == spv::OpMemberDecorateString;
}


} // namespace

std::string literalString(const std::vector<uint32_t>& operands, size_t first) {
    std::string text;
    for (size_t i = first; i < operands.size(); ++i) {
        char bytes[4];
        std::memcpy(bytes, &operands[i], 4);
        for (char c : bytes) {
            if (c == '\0') return text;
            text += c;
        }
    }
    return text;
}

uint32_t entryExecutionModel(const SpirvModule& module) {
    for (size_t i = 0; i < module.size(); ++i)
        if (module.instruction(i).opcode == spv::OpEntryPoint) return module.instruction(i).operands[0];
    return spv::ExecutionModelMax;
}

SpirvModule::SpirvModule(const std::vector<uint32_t>& words) {
    if (words.size() < kHeaderWords) throw std::invalid_argument("SPIR-V module shorter than its header");
    std::copy_n(words.begin(), kHeaderWords, header_.begin());
    for (size_t at = kHeaderWords; at < words.size();) {
        const uint32_t wordCount = words[at] >> spv::WordCountShift;
        if (wordCount == 0 || at + wordCount > words.size()) throw std::invalid_argument("malformed SPIR-V instruction");
        instructions_.push_back({words[at] & spv::OpCodeMask, {words.begin() + at + 1, words.begin() + at + wordCount}});
        at += wordCount;
    }
}

std::vector<uint32_t> SpirvModule::words() const {
    std::vector<uint32_t> words(header_.begin(), header_.end());
    for (const auto& instruction : instructions_) {
        words.push_back(static_cast<uint32_t>(instruction.operands.size() + 1) << spv::WordCountShift | instruction.opcode);
        words.insert(words.end(), instruction.operands.begin(), instruction.operands.end());
    }
    return words;
}

size_t SpirvModule::indexOfDefinition(uint32_t id) const {
    for (size_t i = 0; i < instructions_.size(); ++i) {
        const int at = resultIndex(instructions_[i].opcode);
        if (at >= 0 && static_cast<size_t>(at) < instructions_[i].operands.size() && instructions_[i].operands[at] == id)
            return i;
    }
    return instructions_.size();
}

SpirvInstruction* SpirvModule::definition(uint32_t id) {
    const size_t index = indexOfDefinition(id);
    return index < instructions_.size() ? &instructions_[index] : nullptr;
}

const SpirvInstruction* SpirvModule::definition(uint32_t id) const {
    const size_t index = indexOfDefinition(id);
    return index < instructions_.size() ? &instructions_[index] : nullptr;
}

std::vector<uint32_t> SpirvModule::idsNamed(const std::string& name) const {
    std::vector<uint32_t> ids;
    for (const auto& instruction : instructions_)
        if (instruction.opcode == spv::OpName && literalString(instruction.operands, 1) == name)
            ids.push_back(instruction.operands[0]);
    return ids;
}

uint32_t SpirvModule::pointeeOf(uint32_t pointerType) const {
    const auto* pointer = definition(pointerType);
    return pointer && pointer->opcode == spv::OpTypePointer ? pointer->operands[2] : 0;
}

size_t SpirvModule::usesOf(uint32_t id) const {
    size_t uses = 0;
    for (const auto& instruction : instructions_) {
        if (isNameOrDecoration(instruction.opcode)) continue;
        const int own = resultIndex(instruction.opcode);
        for (size_t i = 0; i < instruction.operands.size(); ++i)
            if (instruction.operands[i] == id && static_cast<int>(i) != own) ++uses;
    }
    return uses;
}

std::vector<uint32_t> SpirvModule::loadsOf(uint32_t variable) const {
    std::vector<uint32_t> loads;
    for (const auto& instruction : instructions_)
        if (instruction.opcode == spv::OpLoad && instruction.operands[2] == variable) loads.push_back(instruction.operands[1]);
    return loads;
}

uint32_t SpirvModule::findTypeLike(const SpirvInstruction& type) const {
    for (const auto& instruction : instructions_)
        if (instruction.opcode == type.opcode && instruction.operands.size() == type.operands.size() &&
            std::equal(instruction.operands.begin() + 1, instruction.operands.end(), type.operands.begin() + 1))
            return instruction.operands[0];
    return 0;
}

uint32_t SpirvModule::findUniformConstantPointer(uint32_t pointee) const {
    for (const auto& instruction : instructions_)
        if (instruction.opcode == spv::OpTypePointer && instruction.operands[1] == spv::StorageClassUniformConstant &&
            instruction.operands[2] == pointee)
            return instruction.operands[0];
    return 0;
}

uint32_t SpirvModule::cloneTypeAfter(uint32_t typeId, uint32_t afterId) {
    SpirvInstruction clone = *definition(typeId);
    const uint32_t newId = this->newId();
    clone.operands[0] = newId;
    instructions_.insert(instructions_.begin() + static_cast<std::ptrdiff_t>(indexOfDefinition(afterId)) + 1, clone);
    return newId;
}

void SpirvModule::retypeVariable(uint32_t variable, uint32_t newPointer, uint32_t oldImage, uint32_t newImage) {
    definition(variable)->operands[0] = newPointer;
    for (auto& instruction : instructions_)
        if (instruction.opcode == spv::OpLoad && instruction.operands[2] == variable && instruction.operands[0] == oldImage)
            instruction.operands[0] = newImage;
}

uint32_t SpirvModule::newId() { return header_[kIdBoundWord]++; }

const SpirvInstruction* SpirvModule::storageImageTypeOf(uint32_t variable) const {
    const auto* declaration = definition(variable);
    if (!declaration || declaration->opcode != spv::OpVariable) return nullptr;
    const auto* image = definition(pointeeOf(declaration->operands[0]));
    return image && image->opcode == spv::OpTypeImage && image->operands[kImageSampled] == 2 ? image : nullptr;
}

size_t SpirvModule::afterLastAnnotation() const {
    size_t after = 0;
    for (size_t i = 0; i < instructions_.size(); ++i) {
        const uint32_t opcode = instructions_[i].opcode;
        if (opcode == spv::OpDecorate || opcode == spv::OpMemberDecorate || opcode == spv::OpName ||
            opcode == spv::OpMemberName || opcode == spv::OpDecorateString || opcode == spv::OpMemberDecorateString)
            after = i + 1;
    }
    return after;
}

void SpirvModule::insertBefore(size_t index, SpirvInstruction instruction) {
    instructions_.insert(instructions_.begin() + static_cast<std::ptrdiff_t>(index), std::move(instruction));
}

uint32_t SpirvModule::typeOf(uint32_t id) const {
    const auto* value = definition(id);
    return value && resultIndex(value->opcode) == 1 ? value->operands[0] : 0;
}

uint32_t SpirvModule::declareOnce(SpirvInstruction declaration) {
    const int result = resultIndex(declaration.opcode);
    for (const auto& instruction : instructions_) {
        if (instruction.opcode != declaration.opcode || instruction.operands.size() != declaration.operands.size()) continue;
        bool same = true;
        for (size_t i = 0; i < instruction.operands.size() && same; ++i)
            same = static_cast<int>(i) == result || instruction.operands[i] == declaration.operands[i];
        if (same) return instruction.operands[result];
    }
    const uint32_t id = newId();
    declaration.operands[result] = id;
    const auto firstFunction = std::find_if(instructions_.begin(), instructions_.end(),
                                            [](const SpirvInstruction& instruction) { return instruction.opcode == spv::OpFunction; });
    instructions_.insert(firstFunction, std::move(declaration));
    return id;
}

void SpirvModule::requireCapability(uint32_t capability) {
    for (const auto& instruction : instructions_)
        if (instruction.opcode == spv::OpCapability && instruction.operands[0] == capability) return;
    instructions_.insert(instructions_.begin(), SpirvInstruction{spv::OpCapability, {capability}});
}

bool SpirvModule::dropCapability(uint32_t capability) {
    const auto declared = std::find_if(instructions_.begin(), instructions_.end(), [&](const SpirvInstruction& instruction) {
        return instruction.opcode == spv::OpCapability && instruction.operands[0] == capability;
    });
    if (declared == instructions_.end()) return false;
    instructions_.erase(declared);
    return true;
}

void SpirvModule::requireExtension(const std::string& name) {
    // A literal string: its bytes, NUL-terminated, packed little-endian into words.
    std::vector<uint32_t> words((name.size() + 4) / 4, 0);
    for (size_t i = 0; i < name.size(); ++i) words[i / 4] |= uint32_t(uint8_t(name[i])) << (8 * (i % 4));
    size_t at = 0;
    for (; at < instructions_.size(); ++at) {
        const auto& instruction = instructions_[at];
        if (instruction.opcode == spv::OpExtension && instruction.operands == words) return;
        if (instruction.opcode != spv::OpCapability && instruction.opcode != spv::OpExtension) break;
    }
    instructions_.insert(instructions_.begin() + ptrdiff_t(at), SpirvInstruction{spv::OpExtension, words});
}

void SpirvModule::replaceStorageImageFormat(uint32_t from, uint32_t to) {
    constexpr size_t kSampled = 6, kFormat = 7;
    for (auto& instruction : instructions_)
        if (instruction.opcode == spv::OpTypeImage && instruction.operands.size() > kFormat &&
            instruction.operands[kSampled] == 2 && instruction.operands[kFormat] == from)
            instruction.operands[kFormat] = to;
}

} // namespace iblkit::compiler
