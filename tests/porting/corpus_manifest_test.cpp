// A corpus manifest that cannot be what it claims is one error naming the file, the key and the
// problem.
#include "corpus_manifest.hpp"
#include "porting_error.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

namespace iblkit::porting {
namespace {

std::string errorOf(const std::string& manifest) {
    iblkit::testing::TempFolder folder;
    folder.write("Shader.hlsl", "[numthreads(1, 1, 1)] void main() {}\n");
    folder.write("Run.hlsl", "[numthreads(1, 1, 1)] void main() {}\n");
    folder.write("Run.run.json", R"({"shader": "Run.hlsl", "dispatch": {"threads": [1, 1, 1]}})");
    folder.write("Other.hlsl", "[numthreads(1, 1, 1)] void main() {}\n");
    folder.write("Other.run.json", R"({"shader": "Shader.hlsl", "dispatch": {"threads": [1, 1, 1]}})");
    folder.write("corpus.json", manifest);
    try {
        readCorpusManifest(folder.path());
    } catch (const PortingError& error) {
        return error.what();
    }
    return "";
}

std::string withFeature(const std::string& fields) {
    return R"({"features": [{"id": "f", "group": "sm5", "feature": "a feature", "shader": "Shader.hlsl")" + fields + "}]}";
}

TEST(CorpusManifest, AGoodManifestIsRead) {
    iblkit::testing::TempFolder folder;
    folder.write("Shader.hlsl", "[numthreads(1, 1, 1)] void main() {}\n");
    folder.write("corpus.json", withFeature(R"(, "kit": ["enums"], "refused_forms": ["glsl"])"));
    const auto manifest = readCorpusManifest(folder.path());
    ASSERT_EQ(manifest.features.size(), 1u);
    EXPECT_EQ(manifest.features[0].kitEdits, std::vector<std::string>{"enums"});
    EXPECT_EQ(manifest.features[0].refusedForms.count(compiler::CrossTarget::Glsl), 1u);
    ASSERT_EQ(manifest.shaders.size(), 1u);
    EXPECT_FALSE(manifest.shaders[0].runFile);
}

TEST(CorpusManifest, EachProblemIsNamed) {
    EXPECT_NE(errorOf("{").find("not valid JSON"), std::string::npos);
    EXPECT_NE(errorOf(R"({"features": [{"id": "f", "group": "sm5", "feature": "x", "shader": "Other.hlsl"}]})")
                  .find("Other.run.json: runs"),
              std::string::npos)
        << "a run file that runs another shader";
    EXPECT_NE(errorOf(withFeature(R"(, "kit": ["magic"])")).find("'magic' is not one of the kit's edits"), std::string::npos);
    EXPECT_NE(errorOf(withFeature(R"(, "refused_forms": ["spirv"])")).find("'spirv' is not a form"), std::string::npos);
    EXPECT_NE(errorOf(withFeature(R"(, "colour": 1)")).find("colour"), std::string::npos);
    EXPECT_NE(errorOf(R"({"features": [{"id": "f", "group": "sm9", "feature": "x", "shader": "Shader.hlsl"}]})").find("group"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"features": [{"id": "f", "group": "sm5", "feature": "x", "shader": "Missing.hlsl"}]})")
                  .find("no such file: Missing.hlsl"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"features": [{"id": "f", "group": "sm5", "feature": "x", "shader": "Run.hlsl"}],
                         "compile": {"Run.hlsl": {"stage": "frag"}}})")
                  .find("a shader with a run file is compiled as its run file says"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"features": [{"id": "f", "group": "sm5", "feature": "x", "shader": "Shader.hlsl"},
                                       {"id": "f", "group": "sm5", "feature": "y", "shader": "Shader.hlsl"}]})")
                  .find("features[1].id: 'f' is another feature's id too"),
              std::string::npos);
    EXPECT_NE(errorOf(withFeature(R"(, "error": "refused", "kit": ["enums"])")).find("a refused feature"), std::string::npos);
    EXPECT_NE(errorOf(withFeature("") .substr(0, withFeature("").size() - 1) + R"(, "compile": {"Other.hlsl": {}}})")
                  .find("names a shader no feature uses"),
              std::string::npos);
}

} // namespace
} // namespace iblkit::porting
