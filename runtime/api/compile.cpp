#include <iblkit/compile.hpp>

#include "api/error_translation.hpp"

#include "compiler.hpp"

#include <array>
#include <set>
#include <string>
#include <utility>

namespace iblkit {
namespace {

constexpr std::array<std::pair<ShaderForm, compiler::CrossTarget>, 6> kForms{{
    {ShaderForm::Glsl, compiler::CrossTarget::Glsl},
    {ShaderForm::Essl, compiler::CrossTarget::Essl},
    {ShaderForm::Msl, compiler::CrossTarget::Msl},
    {ShaderForm::Hlsl, compiler::CrossTarget::Hlsl},
    {ShaderForm::VulkanGlsl, compiler::CrossTarget::VulkanGlsl},
    {ShaderForm::VulkanEssl, compiler::CrossTarget::VulkanEssl},
}};

compiler::CrossTarget targetOf(ShaderForm form) {
    for (const auto& [public_, target] : kForms)
        if (public_ == form) return target;
    throw Error(ErrorKind::BadInput, "unknown shader form " + std::to_string(int(form)));
}

ShaderForm formOf(compiler::CrossTarget target) {
    for (const auto& [form, internal] : kForms)
        if (internal == target) return form;
    throw Error(ErrorKind::CompileFailed, "internal error: a form the library does not name");
}

constexpr std::array<std::pair<ShaderStage, compiler::ShaderStage>, 6> kStages{{
    {ShaderStage::Vertex, compiler::ShaderStage::Vertex},
    {ShaderStage::TessControl, compiler::ShaderStage::TessControl},
    {ShaderStage::TessEvaluation, compiler::ShaderStage::TessEvaluation},
    {ShaderStage::Geometry, compiler::ShaderStage::Geometry},
    {ShaderStage::Fragment, compiler::ShaderStage::Fragment},
    {ShaderStage::Compute, compiler::ShaderStage::Compute},
}};

compiler::ShaderStage stageOf(ShaderStage stage) {
    for (const auto& [public_, internal] : kStages)
        if (public_ == stage) return internal;
    throw Error(ErrorKind::BadInput, "unknown shader stage " + std::to_string(int(stage)));
}

compiler::BindingShifts bindingShiftsOf(const BindingShifts& shifts) {
    const std::array<std::pair<compiler::RegisterClass, uint32_t>, 4> classes{{
        {compiler::RegisterClass::ConstantBuffer, shifts.constantBuffers},
        {compiler::RegisterClass::ShaderResource, shifts.shaderResources},
        {compiler::RegisterClass::Sampler, shifts.samplers},
        {compiler::RegisterClass::UnorderedAccess, shifts.unorderedAccess},
    }};
    compiler::BindingShifts result;
    for (const auto& [registerClass, shift] : classes) {
        if (shift > compiler::kLargestBinding)
            throw Error(ErrorKind::BadInput, "error: binding shift " + std::string(1, compiler::registerLetter(registerClass)) +
                                                 "=" + std::to_string(shift) + ": bindings end at " +
                                                 std::to_string(compiler::kLargestBinding) + " (glslang holds them in 16 bits)");
        result.set(registerClass, shift);
    }
    return result;
}

compiler::OptimizationLevel optimizationOf(Optimization optimization) {
    switch (optimization) {
    case Optimization::Performance: return compiler::OptimizationLevel::Performance;
    case Optimization::Size: return compiler::OptimizationLevel::Size;
    case Optimization::None: break;
    }
    return compiler::OptimizationLevel::None;
}

compiler::CompileOptions compileOptionsOf(const CompileRequest& request) {
    compiler::CompileOptions options;
    options.source = request.source;
    options.sourceText = request.sourceText;
    options.entryPoint = request.entryPoint;
    if (request.stage) options.stage = stageOf(*request.stage);
    options.includeDirs = request.includeDirs;
    options.defines = request.defines;
    options.imageFormats = request.imageFormats;
    options.bindingShifts = bindingShiftsOf(request.bindingShifts);
    options.optimization = optimizationOf(request.optimization);
    options.stripDebugInfo = request.stripDebugInfo;
    options.hlslVersion =
        request.hlslVersion == HlslVersion::Hlsl2018 ? lowering::HlslVersion::Hlsl2018 : lowering::HlslVersion::Hlsl2021;
    options.enable16BitTypes = request.enable16BitTypes;
    options.boundPreprocessing = request.boundPreprocessing;
    return options;
}

CompileResult resultOf(const CompileRequest& request, const compiler::CompiledShader& shader,
                       const compiler::ShaderForms& forms) {
    CompileResult result;
    result.spirv = shader.spirv;
    for (const auto& [target, form] : forms.produced) result.forms[formOf(target)] = form.source;
    for (const auto& [target, reason] : forms.refused) result.refusedForms[formOf(target)] = reason;
    result.reflectionJson = compiler::reflectionJson(shader, forms.produced, forms.refused);
    if (!request.depfileTarget.empty()) result.depfile = compiler::makeDepfile(request.depfileTarget, shader);
    result.includedFiles.assign(shader.includedFiles.begin(), shader.includedFiles.end());
    result.warnings = shader.warnings;
    return result;
}

} // namespace

std::string_view shaderFormName(ShaderForm form) { return compiler::crossTargetName(targetOf(form)); }

std::optional<ShaderStage> shaderStageNamed(std::string_view name) {
    const auto stage = compiler::parseStageName(name);
    for (const auto& [public_, internal] : kStages)
        if (stage == internal) return public_;
    return std::nullopt;
}

CompileResult compileShader(const CompileRequest& request) {
    const auto options = api::translated(ErrorKind::BadInput, [&] { return compileOptionsOf(request); });
    return api::translated(ErrorKind::CompileFailed, [&] {
        const auto shader = compiler::compileShader(options);
        std::set<compiler::CrossTarget> targets;
        for (const auto form : request.forms) targets.insert(targetOf(form));
        return resultOf(request, shader, compiler::crossCompileForms(shader, targets));
    });
}

} // namespace iblkit
