#pragma once

#include "compiler.hpp"
#include "shader_manifest.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace iblkit::testing {

inline const char* kManifest = "hlsl/shaders.json";

// The manifest entry of a seed shader: the options the build compiles it with.
inline compiler::ManifestShader manifestShader(const std::string& name) {
    for (auto& shader : compiler::readShaderManifest(kManifest))
        if (shader.name == name) return shader;
    throw std::out_of_range("no shader " + name + " in " + kManifest);
}

inline compiler::CompiledShader compileSeed(const std::string& name) {
    return compiler::compileShader(manifestShader(name).options);
}

} // namespace iblkit::testing
