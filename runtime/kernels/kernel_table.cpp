#include "kernels/kernel_table.hpp"

#include "compiler.hpp"
#include "kernels/built_in_kernels.hpp"
#include "kernels/compiled_kernel_cache.hpp"
#include "shader_manifest.hpp"

#include <algorithm>
#include <stdexcept>

namespace iblkit::kernels {
namespace {

constexpr std::pair<std::string_view, KernelRole> kRoles[] = {
    {"brdf-lut", KernelRole::BrdfLut},
    {"brdf-lut-chunk", KernelRole::BrdfLutChunk},
    {"brdf-lut-grid", KernelRole::BrdfLutGrid},
    {"brdf-lut-resample", KernelRole::BrdfLutResample},
    {"prefilter", KernelRole::Prefilter},
    {"prefilter-chunk", KernelRole::PrefilterChunk},
    {"prefilter-table", KernelRole::PrefilterTable},
    {"prefilter-pyramid", KernelRole::PrefilterPyramid},
    {"prefilter-ring", KernelRole::PrefilterRing},
    {"cluster-cube", KernelRole::ClusterCube},
    {"prefilter-convolution", KernelRole::PrefilterConvolution},
    {"sky-cube", KernelRole::SkyCube},
    {"equirect-to-cube", KernelRole::EquirectToCube},
    {"downsample-cube", KernelRole::DownsampleCube},
    {"sh-project", KernelRole::ShProject},
    {"irradiance-cube", KernelRole::IrradianceCube},
    {"preview", KernelRole::Preview},
    {"render-reference", KernelRole::RenderReference},
    {"render-split-sum", KernelRole::RenderSplitSum},
    {"probe", KernelRole::Probe},
};

KernelRole parseRole(const std::string& shader, const std::string& name) {
    for (const auto& [text, role] : kRoles)
        if (text == name) return role;
    throw std::invalid_argument("hlsl/shaders.json: shader " + shader + " has an unknown kernel role '" + name + "'");
}

std::vector<KernelEntry> readTable() {
    const auto& files = embeddedShaderFiles();
    std::vector<KernelEntry> table;
    for (auto& shader : compiler::parseShaderManifest(files.at("hlsl/shaders.json"), "hlsl/shaders.json")) {
        const auto source = shader.options.source.generic_string();
        const bool document = source.starts_with("hlsl/document/");
        table.push_back({shader.name, parseRole(shader.name, shader.kernel), shader.methods, document,
                         std::move(shader.options)});
    }
    return table;
}

} // namespace

bool KernelEntry::belongsTo(std::string_view method) const {
    return std::find(methods.begin(), methods.end(), method) != methods.end();
}

std::string_view roleName(KernelRole role) {
    for (const auto& [text, each] : kRoles)
        if (each == role) return text;
    return "?";
}

const std::vector<KernelEntry>& kernelTable() {
    static const std::vector<KernelEntry> table = readTable();
    return table;
}

const KernelEntry& kernelNamed(std::string_view name) {
    for (const auto& kernel : kernelTable())
        if (kernel.name == name) return kernel;
    throw std::out_of_range("no kernel named '" + std::string(name) + "' in hlsl/shaders.json");
}

const KernelEntry& kernelFor(KernelRole role, std::string_view method) {
    for (const auto& kernel : kernelTable())
        if (kernel.role == role && (method.empty() || kernel.belongsTo(method))) return kernel;
    throw std::out_of_range("no " + std::string(roleName(role)) + " kernel" +
                            (method.empty() ? std::string() : " of method '" + std::string(method) + "'") +
                            " in hlsl/shaders.json");
}

std::vector<std::string> methodsOf(KernelRole role) {
    std::vector<std::string> methods;
    for (const auto& kernel : kernelTable())
        if (kernel.role == role) methods.insert(methods.end(), kernel.methods.begin(), kernel.methods.end());
    return methods;
}

compiler::CompileOptions optionsReading(const KernelEntry& kernel, const ShaderFiles& files) {
    auto options = kernel.options;
    const auto source = options.source.generic_string();
    const auto text = files.find(source);
    if (text == files.end()) throw std::out_of_range("the shader files have no " + source);
    options.sourceText = text->second;
    options.virtualFiles = files;
    return options;
}

KernelProgram compileKernel(const KernelEntry& kernel, const std::map<std::string, std::string>& defines,
                            const std::map<std::string, std::string>& imageFormats, const ShaderFiles& files) {
    auto options = optionsReading(kernel, files);
    for (const auto& [name, value] : defines) options.defines[name] = value;
    for (const auto& [name, format] : imageFormats) options.imageFormats[name] = format;
    auto* counter = kernelCompileCounterInUse();
    if (auto program = builtInKernel(options)) {
        if (counter) ++counter->builtIn;
        return std::move(*program);
    }
    auto* cache = compiledKernelCacheInUse();
    if (cache)
        if (auto program = cache->find(options)) return std::move(*program);
    const auto shader = compiler::compileShader(options);
    if (counter) ++counter->compiled;
    if (cache) cache->keep(options, shader);
    return {shader.spirv, shader.reflection};
}

} // namespace iblkit::kernels
