#pragma once

#include "compile_options.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::compiler {

struct ManifestShader {
    std::string name; // the base name of every output form
    CompileOptions options;
};

// Reads hlsl/shaders.json: every shader the kit compiles with its entry point, defines and
// image formats; sources and include folders relative to the manifest's folder, which is
// always an include folder. Throws CompileError.
std::vector<ManifestShader> readShaderManifest(const std::filesystem::path& manifest);

// The options of the manifest's shader of that name; throws CompileError when there is none.
CompileOptions manifestShaderOptions(const std::filesystem::path& manifest, const std::string& name);

} // namespace iblkit::compiler
