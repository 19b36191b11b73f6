#include "compile_all_command.hpp"

#include "atomic_output.hpp"
#include "compile_error.hpp"
#include "compiler.hpp"
#include "shader_manifest.hpp"

#include <fmt/core.h>

#include <chrono>
#include <memory>
#include <set>

namespace iblkit::cli {
namespace {

struct CompileAllArguments {
    std::string manifest = "hlsl/shaders.json";
    std::string outputDir;
    std::vector<std::string> only;
};

const std::map<std::string, compiler::CrossTarget> kForms = {{"glsl", compiler::CrossTarget::Glsl},
                                                             {"essl", compiler::CrossTarget::Essl},
                                                             {"msl", compiler::CrossTarget::Msl},
                                                             {"hlsl", compiler::CrossTarget::Hlsl},
                                                             {"vulkan-glsl", compiler::CrossTarget::VulkanGlsl},
                                                             {"vulkan-essl", compiler::CrossTarget::VulkanEssl}};
const std::map<compiler::CrossTarget, std::string> kExtensions = {{compiler::CrossTarget::Glsl, ".glsl"},
                                                                  {compiler::CrossTarget::Essl, ".essl"},
                                                                  {compiler::CrossTarget::Msl, ".metal"},
                                                                  {compiler::CrossTarget::Hlsl, ".hlsl"},
                                                                  {compiler::CrossTarget::VulkanGlsl, ".vk.glsl"},
                                                                  {compiler::CrossTarget::VulkanEssl, ".vk.essl"}};

// The Vulkan-semantics forms are written only when asked for.
std::set<std::string> selectedForms(const std::vector<std::string>& only) {
    const std::set<std::string> byDefault = {"spirv", "glsl", "essl", "msl", "hlsl", "reflect"};
    if (only.empty()) return byDefault;
    for (const auto& form : only)
        if (!byDefault.count(form) && !kForms.count(form))
            throw compiler::CompileError("error: --only: unknown form '" + form +
                                         "' (forms: spirv, glsl, essl, msl, hlsl, vulkan-glsl, vulkan-essl, reflect)");
    return {only.begin(), only.end()};
}

std::string summaryLine(const std::string& name, const compiler::CompiledShader& shader, size_t formCount,
                        std::chrono::duration<double, std::milli> elapsed) {
    const auto& reflection = shader.reflection;
    std::string groups;
    if (reflection.stage == compiler::ShaderStage::Compute)
        groups = fmt::format(" [{}x{}x{}]", reflection.workgroupSize[0], reflection.workgroupSize[1],
                             reflection.workgroupSize[2]);
    const size_t resources = reflection.resources.size();
    return fmt::format("{:<22} {}{:<12} {} resource{}  SPIR-V {:.1f} KiB  {} forms  {:.0f} ms", name,
                       compiler::stageName(reflection.stage), groups, resources, resources == 1 ? "" : "s",
                       shader.spirv.size() * 4 / 1024.0, formCount, elapsed.count());
}

using Outputs = std::vector<std::pair<std::filesystem::path, std::string>>;

// Compiles one shader into the selected forms, in memory.
std::string compileForms(const compiler::ManifestShader& entry, const std::set<std::string>& forms,
                         const std::filesystem::path& outputDir, Outputs& outputs) {
    const auto started = std::chrono::steady_clock::now();
    auto options = entry.options;
    options.boundPreprocessing = true;
    const auto shader = compiler::compileShader(options);
    for (const auto& warning : shader.warnings) fmt::print(stderr, "{}\n", warning);
    const std::string base = (outputDir / entry.name).string();
    if (forms.count("spirv"))
        outputs.emplace_back(base + ".spv", std::string(reinterpret_cast<const char*>(shader.spirv.data()),
                                                        shader.spirv.size() * sizeof(uint32_t)));
    std::set<compiler::CrossTarget> targets;
    for (const auto& [form, target] : kForms)
        if (forms.count(form)) targets.insert(target);
    const auto compiled = compiler::crossCompileForms(shader, targets);
    for (const auto& [target, form] : compiled.produced) outputs.emplace_back(base + kExtensions.at(target), form.source);
    // A refused form is no failure of the manifest: its reason is printed and kept in the reflection.
    for (const auto& [target, reason] : compiled.refused) fmt::print(stderr, "{}\n", reason);
    if (forms.count("reflect"))
        outputs.emplace_back(base + ".json", compiler::reflectionJson(shader, compiled.produced, compiled.refused));
    return summaryLine(entry.name, shader, forms.size() - compiled.refused.size(), std::chrono::steady_clock::now() - started);
}

void runCompileAll(const CompileAllArguments& arguments) {
    const auto forms = selectedForms(arguments.only);
    const auto shaders = compiler::readShaderManifest(arguments.manifest);
    Outputs outputs;
    std::vector<std::string> summaries;
    for (const auto& entry : shaders) summaries.push_back(compileForms(entry, forms, arguments.outputDir, outputs));

    std::error_code error;
    std::filesystem::create_directories(arguments.outputDir, error);
    if (error) throw files::FileError(arguments.outputDir + ": error: cannot create the folder: " + error.message());
    files::AtomicOutput output;
    for (auto& [path, contents] : outputs) output.add(path, std::move(contents));
    output.commit();
    for (const auto& line : summaries) fmt::print("{}\n", line);
}

} // namespace

void addCompileAllCommand(CLI::App& app) {
    auto arguments = std::make_shared<CompileAllArguments>();
    auto* command = app.add_subcommand("compile-all", "Compile every shader of a manifest into every form");
    command->add_option("manifest", arguments->manifest, "Shader manifest (default hlsl/shaders.json)");
    command->add_option("-o,--output-dir", arguments->outputDir, "Folder for the outputs")->required();
    command->add_option("--only", arguments->only, "Forms to write: spirv, glsl, essl, msl, hlsl, reflect (the default), vulkan-glsl, vulkan-essl")
        ->delimiter(',');
    command->callback([arguments] { runCompileAll(*arguments); });
}

} // namespace iblkit::cli
