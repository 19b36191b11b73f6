#include "spirv_texel_widening.hpp"

#include "image_formats.hpp"
#include "spirv_module.hpp"

#include <spirv/unified1/spirv.hpp>

#include <algorithm>
#include <bit>

namespace iblkit::compiler {
namespace {

constexpr size_t kImageSampledType = 1, kImageFormat = 7;

uint32_t channelsOf(uint32_t spirvFormat) {
    const auto* format = findImageFormat(spirvFormat);
    if (!format) return 0; // Unknown: the write decides
    std::string name(format->glslName);
    if (const auto at = name.find("_snorm"); at != std::string::npos) name.erase(at);
    return static_cast<uint32_t>(std::count_if(name.begin(), name.end(), [](char c) { return c == 'r' || c == 'g' || c == 'b' || c == 'a'; }));
}

class TexelWidening {
public:
    explicit TexelWidening(SpirvModule& module) : module_(module) {}

    void run() {
        for (size_t i = 0; i < module_.size(); ++i)
            if (module_.instruction(i).opcode == spv::OpImageWrite && widen(i)) ++i;
    }

private:
    // Returns whether an instruction was inserted before index.
    bool widen(size_t index) {
        const auto& write = module_.instruction(index);
        const auto* image = module_.definition(module_.typeOf(write.operands[0]));
        if (!image || image->opcode != spv::OpTypeImage) return false;
        const uint32_t texel = write.operands[2];
        const auto* texelType = module_.definition(module_.typeOf(texel));
        if (!texelType) return false;
        const uint32_t components = texelType->opcode == spv::OpTypeVector ? texelType->operands[2] : 1;
        if (components >= 4 || components >= channelsOf(image->operands[kImageFormat])) return false;

        const uint32_t component = image->operands[kImageSampledType];
        const uint32_t vector4 = module_.declareOnce({spv::OpTypeVector, {0, component, 4}});
        const bool isFloat = module_.definition(component)->opcode == spv::OpTypeFloat;
        const uint32_t zero = module_.declareOnce({spv::OpConstant, {component, 0, 0}});
        const uint32_t one = module_.declareOnce({spv::OpConstant, {component, 0, isFloat ? std::bit_cast<uint32_t>(1.0f) : 1u}});
        std::vector<uint32_t> operands{vector4, module_.newId(), texel};
        for (uint32_t filled = components; filled < 3; ++filled) operands.push_back(zero);
        operands.push_back(one);
        // declareOnce may have inserted declarations before the functions, moving this write.
        while (module_.instruction(index).opcode != spv::OpImageWrite || module_.instruction(index).operands[2] != texel) ++index;
        const uint32_t widened = operands[1];
        module_.instruction(index).operands[2] = widened;
        module_.insertBefore(index, {spv::OpCompositeConstruct, std::move(operands)});
        return true;
    }

    SpirvModule& module_;
};

} // namespace

std::vector<uint32_t> widenStorageImageWrites(const std::vector<uint32_t>& spirv) {
    SpirvModule module(spirv);
    TexelWidening(module).run();
    return module.words();
}

} // namespace iblkit::compiler
