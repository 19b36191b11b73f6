#include "compile_command.hpp"

#include "atomic_output.hpp"
#include "command_line.hpp"
#include "register_binding.hpp"

#include <iblkit/compile.hpp>
#include <iblkit/error.hpp>

#include <fmt/core.h>

#include <memory>

namespace iblkit::cli {
namespace {

struct CompileArguments {
    std::string source;
    std::string output;
    std::string entry = "main";
    std::string stage;
    std::vector<std::string> includeDirs;
    std::vector<std::string> defines;
    std::vector<std::string> imageFormats;
    std::vector<std::string> bindingShifts;
    bool optimize = false;
    bool optimizeSize = false;
    bool strip = false;
    std::map<ShaderForm, std::string> forms;
    std::string reflect;
    bool writeDepfile = false;
    std::string depfile;
    int hlslVersion = 2021;
    bool enable16BitTypes = false;
};

// --binding-shift CLASS=N, each over the rule's defaults, as the compiler spells and checks them.
BindingShifts bindingShiftsOf(const std::vector<std::string>& flags) {
    compiler::BindingShifts shifts;
    for (const auto& shift : flags) compiler::parseBindingShift(shift, shifts);
    using compiler::RegisterClass;
    return {shifts.of(RegisterClass::ConstantBuffer), shifts.of(RegisterClass::ShaderResource),
            shifts.of(RegisterClass::Sampler), shifts.of(RegisterClass::UnorderedAccess)};
}

CompileRequest toRequest(const CompileArguments& arguments) {
    CompileRequest request;
    request.source = arguments.source;
    request.boundPreprocessing = true;
    request.entryPoint = arguments.entry;
    if (!arguments.stage.empty()) {
        request.stage = shaderStageNamed(arguments.stage);
        if (!request.stage)
            throw Error(ErrorKind::BadInput, "error: unsupported stage '" + arguments.stage +
                                                 "' (supported: vert, tesc, tese, geom, frag, comp)");
    }
    request.includeDirs.assign(arguments.includeDirs.begin(), arguments.includeDirs.end());
    for (const auto& define : arguments.defines) request.defines.insert(splitAssignment(define));
    for (const auto& format : arguments.imageFormats) {
        auto [name, value] = splitAssignment(format);
        if (value.empty()) throw Error(ErrorKind::BadInput, "error: --image-format expects NAME=FORMAT, got '" + format + "'");
        request.imageFormats[name] = value;
    }
    request.bindingShifts = bindingShiftsOf(arguments.bindingShifts);
    request.optimization = arguments.optimizeSize ? Optimization::Size
                           : arguments.optimize   ? Optimization::Performance
                                                  : Optimization::None;
    request.stripDebugInfo = arguments.strip;
    request.enable16BitTypes = arguments.enable16BitTypes;
    request.hlslVersion = arguments.hlslVersion == 2018 ? HlslVersion::Hlsl2018 : HlslVersion::Hlsl2021;
    request.forms.clear();
    for (const auto& [form, path] : arguments.forms) request.forms.insert(form);
    if (arguments.writeDepfile || !arguments.depfile.empty()) request.depfileTarget = arguments.output;
    return request;
}

std::string spirvBytes(const std::vector<uint32_t>& words) {
    return std::string(reinterpret_cast<const char*>(words.data()), words.size() * sizeof(uint32_t));
}

void runCompile(const CompileArguments& arguments) {
    const auto request = toRequest(arguments);
    const auto compiled = compileShader(request);
    for (const auto& warning : compiled.warnings) fmt::print(stderr, "{}\n", warning);

    files::AtomicOutput output;
    std::vector<std::filesystem::path> inputs{arguments.source};
    inputs.insert(inputs.end(), compiled.includedFiles.begin(), compiled.includedFiles.end());
    output.protect(std::move(inputs));
    output.add(arguments.output, spirvBytes(compiled.spirv));
    for (const auto& [form, source] : compiled.forms) output.add(arguments.forms.at(form), source);
    if (!arguments.reflect.empty()) output.add(arguments.reflect, compiled.reflectionJson);
    if (!request.depfileTarget.empty())
        output.add(arguments.depfile.empty() ? arguments.output + ".d" : arguments.depfile, compiled.depfile);
    output.commit();
    // The forms that can express the shader are written; each refused one is a line, and exit 4.
    for (const auto& [form, reason] : compiled.refusedForms) fmt::print(stderr, "{}\n", reason);
    if (!compiled.refusedForms.empty()) throw FormsRefused{};
}

} // namespace

void addCompileCommand(CLI::App& app) {
    auto arguments = std::make_shared<CompileArguments>();
    auto* command = app.add_subcommand("compile", "Compile an HLSL shader to SPIR-V and its other forms");
    command->add_option("source", arguments->source, "HLSL source file")->required();
    command->add_option("-o,--output", arguments->output, "SPIR-V output file")->required();
    command->add_option("-E,--entry", arguments->entry, "Entry point (default main)");
    command->add_option("-S,--stage", arguments->stage, "Stage, when the entry point's attributes do not tell it");
    command->add_option("-I,--include-dir", arguments->includeDirs, "Folder searched for #include")
        ->allow_extra_args(false);
    command->add_option("-D,--define", arguments->defines, "Preprocessor macro NAME[=VALUE]")
        ->allow_extra_args(false);
    command->add_flag("-O", arguments->optimize, "Optimize for performance (SPIRV-Tools)");
    command->add_flag("--Os", arguments->optimizeSize, "Optimize for size (SPIRV-Tools); spelled -Os");
    command->add_flag("--strip", arguments->strip, "Strip debug information from the SPIR-V output");
    command->add_option("--image-format", arguments->imageFormats, "Storage image format NAME=FORMAT (e.g. Precomputed=rg16f)")
        ->allow_extra_args(false);
    command->add_option("--binding-shift", arguments->bindingShifts, "First binding of a register class, CLASS=N (b, t, s, u)")
        ->allow_extra_args(false);
    for (const auto form : {ShaderForm::Glsl, ShaderForm::Essl, ShaderForm::Msl, ShaderForm::Hlsl, ShaderForm::VulkanGlsl,
                            ShaderForm::VulkanEssl}) {
        const std::string name(shaderFormName(form));
        command->add_option_function<std::string>(
            "--" + name, [arguments, form](const std::string& path) { arguments->forms[form] = path; },
            "Also write the " + name + " form");
    }
    command->add_option("--HV,--hlsl-version", arguments->hlslVersion,
                        "HLSL version, 2021 (the default, as in DXC: select, enum, namespace lowered) or 2018; spelled -HV")
        ->check(CLI::IsMember({2018, 2021}));
    command->add_flag("--enable-16bit-types", arguments->enable16BitTypes,
                      "16-bit half, min16* and float16_t/int16_t/uint16_t, as DXC's flag; spelled -enable-16bit-types");
    command->add_option("--reflect", arguments->reflect, "Write the reflection JSON");
    command->add_flag("--MD", arguments->writeDepfile, "Write a depfile (spelled -MD; OUT.d unless -MF)");
    command->add_option("--MF", arguments->depfile, "Depfile path (spelled -MF)");
    command->callback([arguments] { runCompile(*arguments); });
}

} // namespace iblkit::cli
