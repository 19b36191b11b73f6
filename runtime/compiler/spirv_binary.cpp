#include "spirv_binary.hpp"

#include <spirv_cross/spirv.hpp>

#include <cstddef>

namespace iblkit::compiler {

void replaceStorageImageFormat(std::vector<uint32_t>& spirv, unsigned from, unsigned to) {
    constexpr size_t kHeaderWords = 5;
    constexpr uint32_t kSampledOperand = 7, kFormatOperand = 8;
    for (size_t at = kHeaderWords; at < spirv.size();) {
        const uint32_t wordCount = spirv[at] >> spv::WordCountShift;
        const uint32_t opcode = spirv[at] & spv::OpCodeMask;
        if (wordCount == 0) return;
        if (opcode == spv::OpTypeImage && wordCount > kFormatOperand && spirv[at + kSampledOperand] == 2 &&
            spirv[at + kFormatOperand] == from)
            spirv[at + kFormatOperand] = to;
        at += wordCount;
    }
}

} // namespace iblkit::compiler
