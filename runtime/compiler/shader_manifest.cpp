#include "shader_manifest.hpp"

#include "compile_error.hpp"
#include "hlsl_frontend.hpp"
#include "error_words.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>

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

// A shader's name becomes its output files' names in one folder: letters, digits, '_', '-' and
// '.', not starting with '.', so that no name writes outside it, hides a file or is empty.
void requireFileName(const std::string& name) {
    const bool allowed = !name.empty() && name.front() != '.' && name.size() <= 200 &&
                         std::all_of(name.begin(), name.end(), [](unsigned char c) {
                             return std::isalnum(c) || c == '_' || c == '-' || c == '.';
                         });
    if (!allowed)
        throw CompileError("shader name '" + name + "' is not a plain file name (letters, digits, '_', '-' and '.', "
                           "not starting with '.'): it names the output files");
}

void requireKnownKeys(const nlohmann::json& object, const std::string& where, std::initializer_list<const char*> keys) {
    if (!object.is_object()) throw CompileError(where + " must be an object");
    for (const auto& item : object.items())
        if (std::find(keys.begin(), keys.end(), item.key()) == keys.end())
            throw CompileError(where + " has an unknown key '" + item.key() + "'");
}

ManifestShader parseShader(const nlohmann::json& entry, const std::filesystem::path& folder) {
    if (!entry.is_object() || !entry.contains("name") || !entry.at("name").is_string()) throw CompileError("a shader has no \"name\" string");
    ManifestShader shader;
    shader.name = entry.at("name").get<std::string>();
    requireFileName(shader.name);
    requireKnownKeys(entry, "shader " + shader.name, {"name", "source", "entry", "stage", "include", "defines",
                                                      "image_formats", "kernel", "method"});
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
        requireKnownKeys(json, "the manifest", {"comment", "shaders"});
        for (const auto& entry : json.at("shaders")) {
            auto shader = parseShader(entry, manifest.parent_path());
            for (const auto& earlier : shaders)
                if (earlier.name == shader.name)
                    throw CompileError("two shaders are named '" + shader.name + "': their outputs would overwrite each other");
            shaders.push_back(std::move(shader));
        }
    } catch (const nlohmann::json::exception& error) {
        throw CompileError(manifest.string() + ": error: " + files::jsonErrorInWords(error));
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
