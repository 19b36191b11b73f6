#include "compiler.hpp"
#include "thread_group_limits.hpp"

#include "compile_error.hpp"
#include "hlsl_frontend.hpp"
#include "spirv_non_uniform.hpp"
#include "spirv_image_access.hpp"
#include "spirv_image_format.hpp"
#include "spirv_module.hpp"
#include "spirv_glslang_repairs.hpp"
#include "spirv_operand_repairs.hpp"
#include "spirv_semantic_builtins.hpp"
#include "spirv_cbuffer_layout.hpp"
#include "frontend_refusals.hpp"
#include "spirv_texel_widening.hpp"
#include "spirv_wave_prefix.hpp"
#include "spirv_tools.hpp"
#include "spirv_varyings.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace iblkit::compiler {
namespace {

std::string escapeForMake(const std::string& path) {
    std::string escaped;
    for (char c : path) {
        if (c == ' ' || c == '#') escaped += '\\';
        if (c == '$') escaped += '$';
        escaped += c;
    }
    return escaped;
}

nlohmann::json targetJson(const CrossCompiled& compiled) {
    nlohmann::json bindings = nlohmann::json::array();
    for (const auto& binding : compiled.bindings) {
        nlohmann::json entry = {{"resource", binding.resource}, {"namespace", binding.namespace_}, {"slot", binding.slot}};
        if (!binding.declaredName.empty()) entry["declared_name"] = binding.declaredName;
        if (!binding.format.empty()) entry["format"] = binding.format;
        if (!binding.adaptedFrom.empty()) entry["adapted_from"] = binding.adaptedFrom;
        bindings.push_back(std::move(entry));
    }
    return bindings;
}

} // namespace

CompiledShader compileShader(const CompileOptions& options) {
    auto frontend = compileHlsl(options);
    CompiledShader shader;
    shader.sourceName = options.source.string();
    auto imageFormats = frontend.imageFormats; // [[vk::image_format]], where --image-format does not say otherwise
    for (const auto& [resource, format] : options.imageFormats) imageFormats[resource] = format;
    shader.kitEdits = frontend.kitEdits;
    // Repairs of what glslang writes invalid come before legalization, which validates.
    SpirvModule raw(frontend.spirv);
    if (matchAtomicValueTypes(raw)) shader.kitEdits.emplace_back("atomic-value-types");
    if (semanticsAsBuiltIns(raw)) shader.kitEdits.emplace_back("semantic-built-ins");
    if (flattenedArrayLocations(raw)) shader.kitEdits.emplace_back("flattened-array-locations");
    if (decorateFragmentIntegerInputsFlat(raw)) shader.kitEdits.emplace_back("flat-integer-inputs");
    if (logicalOperationsOnBooleans(raw)) shader.kitEdits.emplace_back("boolean-logic");
    const auto varyings = readVaryings(raw); // legalization strips the semantics
    // The kit's own edits of glslang's SPIR-V, on one parse of the legalized module.
    SpirvModule module(legalizeHlslSpirv(raw.words(), shader.sourceName));
    refuseUnportableConstantBufferPacking(module, frontend.packedMembers, shader.sourceName);
    applyImageFormats(module, imageFormats, shader.sourceName);
    if (constantImageOffsets(module)) shader.kitEdits.emplace_back("constant-image-offsets");
    if (widenStorageImageWrites(module)) shader.kitEdits.emplace_back("texel-widening");
    if (makeWavePrefixScansExclusive(module)) shader.kitEdits.emplace_back("exclusive-wave-scans");
    if (decorateStorageImageAccess(module)) shader.kitEdits.emplace_back("image-access-qualifiers");
    const auto& edits = frontend.kitEdits;
    if (std::find(edits.begin(), edits.end(), "non-uniform-resource-index") != edits.end())
        decorateNonUniformResourceIndexing(module);
    const auto legal = module.words();
    try {
        validateSpirv(legal, shader.sourceName);
    } catch (const CompileError& error) {
        throw CompileError(invalidSpirvInKitWords(error.what()));
    }
    shader.reflection = reflectShader(legal, frontend.registers, options.entryPoint, frontend.stage);
    requireDirect3DThreadGroup(shader.reflection, shader.sourceName);
    shader.reflection.varyings = varyings;
    shader.namedSpirv = optimizeSpirv(legal, options.optimization, shader.sourceName);
    if (options.optimization != OptimizationLevel::None) validateSpirv(shader.namedSpirv, shader.sourceName);
    shader.spirv = options.stripDebugInfo ? stripDebugInfo(shader.namedSpirv, shader.sourceName) : shader.namedSpirv;
    if (options.stripDebugInfo) validateSpirv(shader.spirv, shader.sourceName);
    shader.bindingShifts = frontend.bindingShifts;
    shader.includedFiles = std::move(frontend.includedFiles);
    shader.warnings = std::move(frontend.warnings);
    if (auto warning = matrixInputWarning(varyings, frontend.stage == ShaderStage::Vertex, shader.sourceName); !warning.empty())
        shader.warnings.push_back(std::move(warning));
    return shader;
}

CrossCompiled crossCompileShader(const CompiledShader& shader, CrossTarget target) {
    return crossCompile(shader.namedSpirv, shader.reflection, target, shader.sourceName);
}

ShaderForms crossCompileForms(const CompiledShader& shader, const std::set<CrossTarget>& targets) {
    ShaderForms forms;
    for (const auto target : targets) {
        try {
            forms.produced[target] = crossCompileShader(shader, target);
        } catch (const CompileError& error) {
            forms.refused[target] = error.what();
        }
    }
    return forms;
}

std::string reflectionJson(const CompiledShader& shader, const std::map<CrossTarget, CrossCompiled>& targets,
                           const std::map<CrossTarget, std::string>& refused) {
    nlohmann::json json = toJson(shader.reflection);
    json["source"] = shader.sourceName;
    nlohmann::json rule = nlohmann::json::object();
    for (RegisterClass registerClass : kRegisterClasses)
        rule[std::string(1, registerLetter(registerClass))] = shader.bindingShifts.of(registerClass);
    json["binding_shifts"] = rule;
    nlohmann::json targetBindings = nlohmann::json::object();
    for (const auto& [target, compiled] : targets) targetBindings[std::string(crossTargetName(target))] = targetJson(compiled);
    json["targets"] = targetBindings;
    // What a GLSL or ESSL form needs of the driver that reads it: its version and extensions.
    nlohmann::json requirements = nlohmann::json::object();
    for (const auto& [target, compiled] : targets)
        if (compiled.version != 0) requirements[std::string(crossTargetName(target))] = {{"version", compiled.version}, {"extensions", compiled.extensions}};
    if (!requirements.empty()) json["form_requirements"] = requirements;
    if (!refused.empty()) {
        nlohmann::json reasons = nlohmann::json::object();
        for (const auto& [target, reason] : refused) reasons[std::string(crossTargetName(target))] = reason;
        json["refused_forms"] = reasons;
    }
    return json.dump(2) + "\n";
}

std::string makeDepfile(const std::string& target, const CompiledShader& shader) {
    std::string rule = escapeForMake(target) + ": " + escapeForMake(shader.sourceName);
    for (const auto& file : shader.includedFiles) rule += " \\\n  " + escapeForMake(file);
    return rule + "\n";
}

} // namespace iblkit::compiler
