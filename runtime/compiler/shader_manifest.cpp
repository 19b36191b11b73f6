#include "shader_manifest.hpp"

#include "compile_error.hpp"
#include "hlsl_frontend.hpp"

#include <nlohmann/json.hpp>

namespace iblkit::compiler {
namespace {

template <typename T>
T valueOr(const nlohmann::json& object, const char* key, T fallback) {
    return object.contains(key) ? object.at(key).get<T>() : fallback;
}

// "method" names one method, or lists the methods that share the kernel.
std::vector<std::string> methodsOf(const nlohmann::json& entry) {
    if (!entry.contains("method")) return {};
    const auto& method = entry.at("method");
    if (method.is_string()) return {method.get<std::string>()};
    auto methods = method.get<std::vector<std::string>>();
    if (methods.empty()) throw CompileError("shader " + entry.at("name").get<std::string>() + " lists no method");
    return methods;
}

ManifestShader parseShader(const nlohmann::json& entry, const std::filesystem::path& folder) {
    ManifestShader shader;
    shader.name = entry.at("name").get<std::string>();
    shader.options.source = folder / entry.at("source").get<std::string>();
    shader.options.entryPoint = valueOr<std::string>(entry, "entry", "main");
    if (entry.contains("stage")) {
        const auto stage = parseStageName(entry.at("stage").get<std::string>());
        if (!stage) throw CompileError("unknown stage '" + entry.at("stage").get<std::string>() + "'");
        shader.options.stage = stage;
    }
    shader.options.includeDirs.push_back(folder);
    for (const auto& dir : valueOr<std::vector<std::string>>(entry, "include", {}))
        shader.options.includeDirs.push_back(folder / dir);
    shader.options.defines = valueOr<std::map<std::string, std::string>>(entry, "defines", {});
    shader.options.imageFormats = valueOr<std::map<std::string, std::string>>(entry, "image_formats", {});
    shader.kernel = valueOr<std::string>(entry, "kernel", "");
    shader.methods = methodsOf(entry);
    return shader;
}

} // namespace

std::vector<ManifestShader> readShaderManifest(const std::filesystem::path& manifest) {
    return parseShaderManifest(readSource(manifest), manifest);
}

std::vector<ManifestShader> parseShaderManifest(const std::string& text, const std::filesystem::path& manifest) {
    std::vector<ManifestShader> shaders;
    try {
        const auto json = nlohmann::json::parse(text);
        for (const auto& entry : json.at("shaders")) shaders.push_back(parseShader(entry, manifest.parent_path()));
    } catch (const nlohmann::json::exception& error) {
        throw CompileError(manifest.string() + ": error: " + error.what());
    } catch (const CompileError& error) {
        throw CompileError(manifest.string() + ": error: " + error.what());
    }
    return shaders;
}

CompileOptions manifestShaderOptions(const std::filesystem::path& manifest, const std::string& name) {
    for (auto& shader : readShaderManifest(manifest))
        if (shader.name == name) return std::move(shader.options);
    throw CompileError(manifest.string() + ": error: no shader named '" + name + "'");
}

} // namespace iblkit::compiler
