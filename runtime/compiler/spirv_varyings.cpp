#include "spirv_varyings.hpp"

#include "spirv_module.hpp"

#include <spirv/unified1/spirv.hpp>

#include <cctype>
#include <map>

namespace iblkit::compiler {
namespace {

// System values that Direct3D matches without an index.
bool takesNoIndex(const std::string& semantic) {
    return semantic.rfind("SV_", 0) == 0 && semantic.rfind("SV_TARGET", 0) != 0 && semantic.rfind("SV_CLIPDISTANCE", 0) != 0 &&
           semantic.rfind("SV_CULLDISTANCE", 0) != 0;
}

std::string builtInName(uint32_t builtIn) {
    switch (builtIn) {
    case spv::BuiltInPosition: return "Position";
    case spv::BuiltInFragCoord: return "FragCoord";
    case spv::BuiltInFragDepth: return "FragDepth";
    case spv::BuiltInVertexIndex: return "VertexIndex";
    case spv::BuiltInInstanceIndex: return "InstanceIndex";
    case spv::BuiltInFrontFacing: return "FrontFacing";
    case spv::BuiltInSampleId: return "SampleId";
    case spv::BuiltInSampleMask: return "SampleMask";
    case spv::BuiltInPrimitiveId: return "PrimitiveId";
    case spv::BuiltInClipDistance: return "ClipDistance";
    case spv::BuiltInCullDistance: return "CullDistance";
    case spv::BuiltInViewIndex: return "ViewIndex";
    case spv::BuiltInSubgroupSize: return "SubgroupSize";
    case spv::BuiltInSubgroupLocalInvocationId: return "SubgroupLocalInvocationId";
    case spv::BuiltInLayer: return "Layer";
    case spv::BuiltInViewportIndex: return "ViewportIndex";
    default: return "BuiltIn" + std::to_string(builtIn);
    }
}

struct Shape {
    std::string componentType = "float";
    uint32_t components = 1, locations = 1;
    bool matrix = false;
};

Shape shapeOf(const SpirvModule& module, uint32_t type) {
    const auto* declaration = module.definition(type);
    if (!declaration) return {};
    switch (declaration->opcode) {
    case spv::OpTypeFloat: return {"float", 1, 1};
    case spv::OpTypeInt: return {declaration->operands.size() > 2 && declaration->operands[2] ? "int" : "uint", 1, 1};
    case spv::OpTypeBool: return {"uint", 1, 1};
    case spv::OpTypeVector: {
        auto shape = shapeOf(module, declaration->operands[1]);
        shape.components = declaration->operands[2];
        return shape;
    }
    case spv::OpTypeMatrix: {
        auto shape = shapeOf(module, declaration->operands[1]);
        shape.locations = declaration->operands[2];
        shape.matrix = true;
        return shape;
    }
    case spv::OpTypeArray: {
        auto shape = shapeOf(module, declaration->operands[1]);
        const auto* length = module.definition(declaration->operands[2]);
        shape.locations *= length && length->operands.size() > 2 ? length->operands[2] : 1;
        return shape;
    }
    default: return {};
    }
}

} // namespace

std::string canonicalSemantic(const std::string& semantic) {
    std::string upper;
    for (const char c : semantic) upper += char(std::toupper(static_cast<unsigned char>(c)));
    if (upper.empty() || std::isdigit(static_cast<unsigned char>(upper.back())) || takesNoIndex(upper)) return upper;
    return upper + "0";
}

std::vector<Varying> readVaryings(const SpirvModule& module) {
    std::map<uint32_t, std::string> semantics, names;
    std::map<uint32_t, uint32_t> locations, builtIns;
    std::vector<uint32_t> interface;
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        const auto& operands = instruction.operands;
        if (instruction.opcode == spv::OpDecorateString && operands.size() > 2 && operands[1] == spv::DecorationUserSemantic)
            semantics[operands[0]] = literalString(operands, 2);
        else if (instruction.opcode == spv::OpDecorate && operands.size() > 2 && operands[1] == spv::DecorationLocation)
            locations[operands[0]] = operands[2];
        else if (instruction.opcode == spv::OpDecorate && operands.size() > 2 && operands[1] == spv::DecorationBuiltIn)
            builtIns[operands[0]] = operands[2];
        else if (instruction.opcode == spv::OpName && operands.size() > 1)
            names[operands[0]] = literalString(operands, 1);
        else if (instruction.opcode == spv::OpEntryPoint && interface.empty()) {
            const size_t afterName = 2 + (literalString(operands, 2).size() + 4) / 4;
            interface.assign(operands.begin() + std::ptrdiff_t(std::min(afterName, operands.size())), operands.end());
        }
    }
    std::vector<Varying> varyings;
    for (const uint32_t id : interface) {
        const auto* variable = module.definition(id);
        if (!variable || variable->opcode != spv::OpVariable) continue;
        const uint32_t storage = variable->operands[2];
        if (storage != spv::StorageClassInput && storage != spv::StorageClassOutput) continue;
        Varying varying;
        varying.input = storage == spv::StorageClassInput;
        const auto semantic = semantics.find(id);
        varying.semantic = canonicalSemantic(semantic != semantics.end() ? semantic->second : names[id]);
        if (const auto location = locations.find(id); location != locations.end()) varying.location = int32_t(location->second);
        if (const auto builtIn = builtIns.find(id); builtIn != builtIns.end()) varying.builtIn = builtInName(builtIn->second);
        const auto shape = shapeOf(module, module.pointeeOf(variable->operands[0]));
        varying.componentType = shape.componentType;
        varying.components = shape.components;
        varying.locations = shape.locations;
        varying.matrix = shape.matrix;
        varyings.push_back(std::move(varying));
    }
    return varyings;
}

std::string matrixInputWarning(const std::vector<Varying>& varyings, bool vertexShader, const std::string& sourceName) {
    if (!vertexShader) return "";
    for (const auto& varying : varyings)
        if (varying.input && varying.matrix && varying.builtIn.empty())
            return sourceName + ": warning: vertex input " + varying.semantic + " is a matrix, which glslang reads a row per "
                   "location (" + std::to_string(varying.locations) + " of " + varying.componentType +
                   std::to_string(varying.components) + "); Direct3D's input layout gives a column-major one (HLSL's "
                   "default) by columns: bind its rows, or declare it row_major, which Direct3D also gives by rows";
    return "";
}

} // namespace iblkit::compiler
