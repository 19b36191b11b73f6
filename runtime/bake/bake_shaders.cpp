#include "bake_shaders.hpp"

#include "compiler.hpp"

namespace iblkit::bake {

BakeShader compileBakeShader(const std::string& name, const std::map<std::string, std::string>& defines,
                             const std::map<std::string, std::string>& imageFormats) {
    const auto& files = embeddedShaderFiles();
    const std::string path = "hlsl/" + name + ".hlsl";
    compiler::CompileOptions options;
    options.source = path;
    options.sourceText = files.at(path);
    options.includeDirs = {"hlsl"};
    options.virtualFiles = files;
    options.defines = defines;
    options.imageFormats = imageFormats;
    const auto shader = compiler::compileShader(options);
    return {shader.spirv, shader.reflection};
}

} // namespace iblkit::bake
