#pragma once

#include "compile_options.hpp"
#include "cross_compile.hpp"

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace iblkit::porting {

enum class FeatureGroup { ShaderModel5, ShaderModel6, Hlsl2021, VulkanAttributes };
inline constexpr FeatureGroup kFeatureGroups[] = {FeatureGroup::ShaderModel5, FeatureGroup::ShaderModel6,
                                                  FeatureGroup::Hlsl2021, FeatureGroup::VulkanAttributes};
std::string_view groupTitle(FeatureGroup group); // "Shader Model 5.x", ...

// One HLSL feature and what the corpus shader that uses it must show: which of the kit's edits
// implement it (compiler::describeKitEdit), which forms cannot express it, which forms are made
// but cannot be read back by the compiler that reads them (glslang reads neither the HLSL
// round trip's `100ull` nor its `Store<float>`), and for a feature the kit refuses, the words
// its error must contain.
struct CorpusFeature {
    std::string id;          // "sm6-wave-prefix"
    std::string description; // markdown: "`WavePrefixSum`, `WavePrefixProduct`, `WavePrefixCountBits`"
    FeatureGroup group = FeatureGroup::ShaderModel5;
    std::string shader; // relative to the corpus folder
    std::vector<std::string> kitEdits;
    std::set<compiler::CrossTarget> refusedForms;
    std::set<compiler::CrossTarget> unreadForms;
    std::string error;   // non-empty: the compiler must refuse the shader with these words
    std::string warning; // non-empty: the compiler must warn with these words
};

// A corpus shader and how to compile it: from its run file (X.run.json beside X.hlsl) when it
// has one, which is then also run; otherwise from the manifest's "compile" entry.
struct CorpusShader {
    std::string name; // relative to the corpus folder
    compiler::CompileOptions options;
    std::optional<std::filesystem::path> runFile;
};

struct CorpusManifest {
    std::filesystem::path folder;
    std::vector<CorpusFeature> features; // in the manifest's order
    std::vector<CorpusShader> shaders;   // each shader a feature names, once, in first-use order
};

// Reads FOLDER/corpus.json. Throws PortingError naming the file, the key and the problem.
CorpusManifest readCorpusManifest(const std::filesystem::path& folder);

} // namespace iblkit::porting
