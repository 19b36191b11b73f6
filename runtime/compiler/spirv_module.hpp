#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::compiler {

struct SpirvInstruction {
    uint32_t opcode;
    std::vector<uint32_t> operands; // every word after the opcode word
};

// Operand positions of OpTypeImage (after the opcode word: result id first).
inline constexpr size_t kImageSampledType = 1, kImageSampled = 6, kImageFormat = 7;

// A SPIR-V module as a list of instructions, for the few edits the compiler makes that
// SPIRV-Tools has no pass for (storage image formats).
class SpirvModule {
public:
    explicit SpirvModule(const std::vector<uint32_t>& words);
    std::vector<uint32_t> words() const;

    SpirvInstruction* definition(uint32_t id);
    const SpirvInstruction* definition(uint32_t id) const;
    std::vector<uint32_t> idsNamed(const std::string& name) const;
    uint32_t pointeeOf(uint32_t pointerType) const; // 0 when not an OpTypePointer
    // The image type of a storage image variable (a RWTexture*), or nullptr.
    const SpirvInstruction* storageImageTypeOf(uint32_t variable) const;
    // How often id is referenced outside names, decorations and its own definition; may
    // over-count (a literal equal to the id), never under-count.
    size_t usesOf(uint32_t id) const;
    // The result ids of every OpLoad from variable.
    std::vector<uint32_t> loadsOf(uint32_t variable) const;

    // A type declared exactly like `type` (same opcode and operands but the result id), or 0.
    uint32_t findTypeLike(const SpirvInstruction& type) const;
    // The UniformConstant pointer type to `pointee`, or 0.
    uint32_t findUniformConstantPointer(uint32_t pointee) const;
    // Declares a copy of a type under a new id right after the declaration of afterId.
    uint32_t cloneTypeAfter(uint32_t typeId, uint32_t afterId);
    // Gives variable the new pointer type and its loads the new image type.
    void retypeVariable(uint32_t variable, uint32_t newPointer, uint32_t oldImage, uint32_t newImage);
    void requireCapability(uint32_t capability);
    // Removes the capability's declaration; returns whether there was one.
    bool dropCapability(uint32_t capability);
    void requireExtension(const std::string& name);

    // For passes that walk the functions: the instructions in order, an insertion before one of
    // them, a fresh id.
    size_t size() const { return instructions_.size(); }
    SpirvInstruction& instruction(size_t index) { return instructions_[index]; }
    const SpirvInstruction& instruction(size_t index) const { return instructions_[index]; }
    void insertBefore(size_t index, SpirvInstruction instruction);
    // The index after the last name or decoration: where a new decoration goes.
    size_t afterLastAnnotation() const;
    uint32_t newId();
    // The result type of a value, 0 for an id without one.
    uint32_t typeOf(uint32_t id) const;
    // A type or constant declared like `declaration` (its result id ignored), declared at the end
    // of the global declarations when there is none yet; returns its id.
    uint32_t declareOnce(SpirvInstruction declaration);
    // Rewrites the format of every storage-image type with format `from`.
    void replaceStorageImageFormat(uint32_t from, uint32_t to);

private:
    size_t indexOfDefinition(uint32_t id) const;

    std::array<uint32_t, 5> header_{};
    std::vector<SpirvInstruction> instructions_;
};

// A literal string operand (an OpName's, a decoration's) from operands[first] on.
std::string literalString(const std::vector<uint32_t>& operands, size_t first);

// The execution model of the module's first entry point, ExecutionModelMax without one.
uint32_t entryExecutionModel(const SpirvModule& module);

} // namespace iblkit::compiler
