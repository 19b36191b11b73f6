#include "spirv_semantic_builtins.hpp"

#include "spirv_module.hpp"

#include <spirv/unified1/spirv.hpp>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <string>

namespace iblkit::compiler {
namespace {


// How many locations a varying of `type` occupies: a 64-bit vector of three or four components
// two, a matrix one per column, an array its length times its element's.
uint32_t locationsOf(const SpirvModule& module, uint32_t type) {
    const auto* declaration = module.definition(type);
    if (!declaration) return 1;
    switch (declaration->opcode) {
    case spv::OpTypeVector: {
        const auto* component = module.definition(declaration->operands[1]);
        const bool wide = component && component->operands.size() > 1 && component->operands[1] == 64;
        return wide && declaration->operands[2] > 2 ? 2 : 1;
    }
    case spv::OpTypeMatrix: return declaration->operands[2] * locationsOf(module, declaration->operands[1]);
    case spv::OpTypeArray: {
        const auto* length = module.definition(declaration->operands[2]);
        return (length ? length->operands[2] : 1) * locationsOf(module, declaration->operands[1]);
    }
    default: return 1;
    }
}

// "@entryPointOutput.pnPatch[3]" -> ("@entryPointOutput.pnPatch", 3), as glslang names a
// flattened array's elements.
std::optional<std::pair<std::string, uint32_t>> flattenedElement(const std::string& name) {
    const size_t open = name.rfind('[');
    if (open == std::string::npos || open == 0 || name.back() != ']' || open + 2 >= name.size()) return std::nullopt;
    const std::string index = name.substr(open + 1, name.size() - open - 2);
    if (index.find_first_not_of("0123456789") != std::string::npos || index.size() > 6) return std::nullopt;
    return std::make_pair(name.substr(0, open), uint32_t(std::stoul(index)));
}

std::string upperCase(std::string text) {
    for (char& c : text) c = char(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

struct BuiltInUse {
    spv::BuiltIn builtIn;
    spv::Capability capability;
    const char* extension; // nullptr where Vulkan 1.1 has it
};

std::optional<BuiltInUse> builtInFor(const std::string& semantic, bool fragmentInput) {
    if (semantic == "SV_VIEWID") return BuiltInUse{spv::BuiltInViewIndex, spv::CapabilityMultiView, nullptr};
    if (semantic == "SV_SHADINGRATE")
        return BuiltInUse{fragmentInput ? spv::BuiltInShadingRateKHR : spv::BuiltInPrimitiveShadingRateKHR,
                          spv::CapabilityFragmentShadingRateKHR, "SPV_KHR_fragment_shading_rate"};
    return std::nullopt;
}


bool isFragment(const SpirvModule& module) { return entryExecutionModel(module) == spv::ExecutionModelFragment; }

bool isPatch(SpirvModule& module, uint32_t variable) {
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        if (instruction.opcode == spv::OpDecorate && instruction.operands[0] == variable && instruction.operands[1] == spv::DecorationPatch)
            return true;
    }
    return false;
}

uint32_t storageClassOf(const SpirvModule& module, uint32_t variable) {
    const auto* definition = module.definition(variable);
    return definition && definition->opcode == spv::OpVariable ? definition->operands[2] : uint32_t(spv::StorageClassMax);
}

// Whether a varying is an array over vertices: a hull shader's inputs and outputs, a domain
// shader's inputs and a geometry shader's inputs. glslang sizes a flattened member's array of
// those by the member's length instead of the vertex count, which no location can mend.
bool isPerVertexArray(SpirvModule& module, uint32_t variable) {
    const uint32_t model = entryExecutionModel(module);
    const bool input = storageClassOf(module, variable) == spv::StorageClassInput;
    return ((model == spv::ExecutionModelTessellationControl || (model == spv::ExecutionModelTessellationEvaluation && input)) &&
            !isPatch(module, variable)) ||
           (model == spv::ExecutionModelGeometry && input);
}

} // namespace

bool semanticsAsBuiltIns(SpirvModule& module) {
    std::map<uint32_t, std::string> semantics; // variable -> its semantic, upper case
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        if (instruction.opcode == spv::OpDecorateString && instruction.operands.size() > 2 &&
            instruction.operands[1] == spv::DecorationUserSemantic)
            semantics[instruction.operands[0]] = upperCase(literalString(instruction.operands, 2));
    }
    const bool fragment = isFragment(module);
    bool changed = false;
    for (size_t i = 0; i < module.size(); ++i) {
        auto& instruction = module.instruction(i);
        if (instruction.opcode != spv::OpDecorate || instruction.operands[1] != spv::DecorationLocation) continue;
        const auto semantic = semantics.find(instruction.operands[0]);
        if (semantic == semantics.end()) continue;
        const bool input = storageClassOf(module, instruction.operands[0]) == spv::StorageClassInput;
        const auto use = builtInFor(semantic->second, fragment && input);
        if (!use) continue;
        instruction.operands[1] = spv::DecorationBuiltIn;
        instruction.operands[2] = use->builtIn;
        module.requireCapability(use->capability);
        if (use->extension) module.requireExtension(use->extension);
        changed = true;
    }
    return changed;
}

bool flattenedArrayLocations(SpirvModule& module) {
    std::map<uint32_t, std::string> names;
    for (size_t i = 0; i < module.size(); ++i)
        if (module.instruction(i).opcode == spv::OpName) names[module.instruction(i).operands[0]] = literalString(module.instruction(i).operands, 1);
    // (storage class, location) -> the Location decorations there, in the module's order.
    std::map<std::pair<uint32_t, uint32_t>, std::vector<size_t>> atLocation;
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        if (instruction.opcode == spv::OpDecorate && instruction.operands[1] == spv::DecorationLocation)
            atLocation[{storageClassOf(module, instruction.operands[0]), instruction.operands[2]}].push_back(i);
    }
    bool changed = false;
    for (const auto& [place, decorations] : atLocation) {
        if (decorations.size() < 2) continue;
        std::vector<std::optional<std::pair<std::string, uint32_t>>> elements;
        for (const size_t at : decorations) elements.push_back(flattenedElement(names[module.instruction(at).operands[0]]));
        if (isPerVertexArray(module, module.instruction(decorations[0]).operands[0])) continue;
        const bool oneArrayInOrder = std::all_of(elements.begin(), elements.end(), [&, k = uint32_t(0)](const auto& element) mutable {
            return element && element->first == elements[0]->first && element->second == k++;
        });
        if (!oneArrayInOrder) continue;
        uint32_t location = place.second;
        for (const size_t at : decorations) {
            const uint32_t variable = module.instruction(at).operands[0];
            module.instruction(at).operands[2] = location;
            location += locationsOf(module, module.pointeeOf(module.typeOf(variable)));
        }
        changed = true;
    }
    return changed;
}

} // namespace iblkit::compiler
