#include "compile_command.hpp"

#include "atomic_output.hpp"
#include "command_line.hpp"
#include "compile_error.hpp"
#include "compiler.hpp"

#include <fmt/core.h>

#include <memory>
#include <set>

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
    std::map<compiler::CrossTarget, std::string> forms;
    std::string reflect;
    bool writeDepfile = false;
    std::string depfile;
    int hlslVersion = 2021;
    bool enable16BitTypes = false;
};

compiler::CompileOptions toOptions(const CompileArguments& arguments) {
    compiler::CompileOptions options;
    options.source = arguments.source;
    options.boundPreprocessing = true;
    options.entryPoint = arguments.entry;
    if (!arguments.stage.empty()) {
        options.stage = compiler::parseStageName(arguments.stage);
        if (!options.stage)
            throw compiler::CompileError("error: unsupported stage '" + arguments.stage +
                                         "' (supported: vert, tesc, tese, geom, frag, comp)");
    }
    options.includeDirs.assign(arguments.includeDirs.begin(), arguments.includeDirs.end());
    for (const auto& define : arguments.defines) options.defines.insert(splitAssignment(define));
    for (const auto& format : arguments.imageFormats) {
        auto [name, value] = splitAssignment(format);
        if (value.empty()) throw compiler::CompileError("error: --image-format expects NAME=FORMAT, got '" + format + "'");
        options.imageFormats[name] = value;
    }
    for (const auto& shift : arguments.bindingShifts) compiler::parseBindingShift(shift, options.bindingShifts);
    options.optimization = arguments.optimizeSize ? compiler::OptimizationLevel::Size
                           : arguments.optimize   ? compiler::OptimizationLevel::Performance
                                                  : compiler::OptimizationLevel::None;
    options.stripDebugInfo = arguments.strip;
    options.enable16BitTypes = arguments.enable16BitTypes;
    options.hlslVersion = arguments.hlslVersion == 2018 ? lowering::HlslVersion::Hlsl2018 : lowering::HlslVersion::Hlsl2021;
    return options;
}

std::string spirvBytes(const std::vector<uint32_t>& words) {
    return std::string(reinterpret_cast<const char*>(words.data()), words.size() * sizeof(uint32_t));
}

void runCompile(const CompileArguments& arguments) {
    const auto shader = compiler::compileShader(toOptions(arguments));
    for (const auto& warning : shader.warnings) fmt::print(stderr, "{}\n", warning);

    files::AtomicOutput output;
    std::vector<std::filesystem::path> inputs{arguments.source};
    inputs.insert(inputs.end(), shader.includedFiles.begin(), shader.includedFiles.end());
    output.protect(std::move(inputs));
    output.add(arguments.output, spirvBytes(shader.spirv));
    std::set<compiler::CrossTarget> targets;
    for (const auto& [target, path] : arguments.forms) targets.insert(target);
    const auto forms = compiler::crossCompileForms(shader, targets);
    for (const auto& [target, form] : forms.produced) output.add(arguments.forms.at(target), form.source);
    if (!arguments.reflect.empty()) output.add(arguments.reflect, compiler::reflectionJson(shader, forms.produced, forms.refused));
    if (arguments.writeDepfile || !arguments.depfile.empty()) {
        const std::string depfile = arguments.depfile.empty() ? arguments.output + ".d" : arguments.depfile;
        output.add(depfile, compiler::makeDepfile(arguments.output, shader));
    }
    output.commit();
    // The forms that can express the shader are written; each refused one is a line, and exit 4.
    for (const auto& [target, reason] : forms.refused) fmt::print(stderr, "{}\n", reason);
    if (!forms.refused.empty()) throw FormsRefused{};
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
    const std::pair<const char*, compiler::CrossTarget> forms[] = {{"--glsl", compiler::CrossTarget::Glsl},
                                                                   {"--essl", compiler::CrossTarget::Essl},
                                                                   {"--msl", compiler::CrossTarget::Msl},
                                                                   {"--hlsl", compiler::CrossTarget::Hlsl},
                                                                   {"--vulkan-glsl", compiler::CrossTarget::VulkanGlsl},
                                                                   {"--vulkan-essl", compiler::CrossTarget::VulkanEssl}};
    for (const auto& [flag, target] : forms)
        command->add_option_function<std::string>(
            flag, [arguments, target = target](const std::string& path) { arguments->forms[target] = path; },
            std::string("Also write the ") + (flag + 2) + " form");
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
