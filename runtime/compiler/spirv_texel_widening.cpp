#include "spirv_texel_widening.hpp"

#include "image_formats.hpp"
#include "spirv_module.hpp"

#include <spirv/unified1/spirv.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <map>

namespace iblkit::compiler {
namespace {

uint32_t channelsOf(uint32_t spirvFormat) {
    const auto* format = findImageFormat(spirvFormat);
    if (!format) return 0; // Unknown: the write decides
    std::string name(format->glslName);
    if (const auto at = name.find("_snorm"); at != std::string::npos) name.erase(at);
    return static_cast<uint32_t>(std::count_if(name.begin(), name.end(), [](char c) { return c == 'r' || c == 'g' || c == 'b' || c == 'a'; }));
}

// What one narrow write needs: its texel's component count and its image's component type.
struct NarrowWrite {
    uint32_t components;
    uint32_t component;
};

// The texel id of every write narrower than its image's format.
std::map<uint32_t, NarrowWrite> narrowWrites(SpirvModule& module) {
    std::map<uint32_t, NarrowWrite> writes;
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& write = module.instruction(i);
        if (write.opcode != spv::OpImageWrite) continue;
        const auto* image = module.definition(module.typeOf(write.operands[0]));
        const auto* texelType = module.definition(module.typeOf(write.operands[2]));
        if (!image || image->opcode != spv::OpTypeImage || !texelType) continue;
        const uint32_t components = texelType->opcode == spv::OpTypeVector ? texelType->operands[2] : 1;
        if (components < 4 && components < channelsOf(image->operands[kImageFormat]))
            writes[write.operands[2]] = {components, image->operands[kImageSampledType]};
    }
    return writes;
}

} // namespace

bool widenStorageImageWrites(SpirvModule& module) {
    const auto writes = narrowWrites(module);
    if (writes.empty()) return false;
    // The declarations first (before the functions), then the widening before each write.
    std::map<uint32_t, std::array<uint32_t, 3>> declared; // component type: vector4, 0, 1
    for (const auto& [texel, write] : writes) {
        const uint32_t component = write.component;
        if (declared.count(component)) continue;
        const bool isFloat = module.definition(component)->opcode == spv::OpTypeFloat;
        declared[component] = {module.declareOnce({spv::OpTypeVector, {0, component, 4}}),
                               module.declareOnce({spv::OpConstant, {component, 0, 0}}),
                               module.declareOnce({spv::OpConstant, {component, 0, isFloat ? std::bit_cast<uint32_t>(1.0f) : 1u}})};
    }
    for (size_t i = 0; i < module.size(); ++i) {
        auto& write = module.instruction(i);
        const auto narrow = write.opcode == spv::OpImageWrite ? writes.find(write.operands[2]) : writes.end();
        if (narrow == writes.end()) continue;
        const auto [vector4, zero, one] = declared.at(narrow->second.component);
        std::vector<uint32_t> operands{vector4, module.newId(), narrow->first};
        for (uint32_t filled = narrow->second.components; filled < 3; ++filled) operands.push_back(zero);
        operands.push_back(one);
        write.operands[2] = operands[1];
        module.insertBefore(i++, {spv::OpCompositeConstruct, std::move(operands)});
    }
    return true;
}

} // namespace iblkit::compiler
