#pragma once

#include "compile_options.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::compiler {

struct ManifestShader {
    std::string name; // the base name of every output form
    CompileOptions options;
    std::string kernel; // the kernel role it plays in a bake ("prefilter", "brdf-lut", ...); empty for none
    std::vector<std::string> methods; // the methods it belongs to, for the roles that have several ("document")
};

// Reads hlsl/shaders.json: every shader the kit compiles with its entry point, defines and
// image formats; sources and include folders relative to the manifest's folder, which is
// always an include folder. Throws CompileError.
std::vector<ManifestShader> readShaderManifest(const std::filesystem::path& manifest);
// The same from the manifest's text; `manifest` names it in messages and its folder is the base.
std::vector<ManifestShader> parseShaderManifest(const std::string& text, const std::filesystem::path& manifest);

// The options of the manifest's shader of that name; throws CompileError when there is none.
CompileOptions manifestShaderOptions(const std::filesystem::path& manifest, const std::string& name);

} // namespace iblkit::compiler
