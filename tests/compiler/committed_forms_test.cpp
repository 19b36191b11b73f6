// glsl/ holds the GLSL, ESSL, MSL and reflection the compiler makes from hlsl/ today;
// `cmake --build build --target refresh-glsl` rewrites it.
#include "compiler.hpp"
#include "read_file.hpp"
#include "seed_test_support.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

namespace iblkit::compiler {
namespace {

namespace fs = std::filesystem;

TEST(CommittedForms, GlslFolderMatchesTheCompilersOutput) {
    const std::map<CrossTarget, std::string> extensions = {
        {CrossTarget::Glsl, ".glsl"}, {CrossTarget::Essl, ".essl"}, {CrossTarget::Msl, ".metal"}};
    std::set<fs::path> expectedFiles;
    for (const auto& entry : readShaderManifest(testing::kManifest)) {
        const auto shader = compileShader(entry.options);
        std::map<CrossTarget, CrossCompiled> forms;
        for (const auto& [target, extension] : extensions) forms[target] = crossCompileShader(shader, target);
        std::map<fs::path, std::string> files;
        for (const auto& [target, extension] : extensions) files["glsl/" + entry.name + extension] = forms[target].source;
        files["glsl/" + entry.name + ".json"] = reflectionJson(shader, forms);
        for (const auto& [path, text] : files) {
            expectedFiles.insert(path);
            ASSERT_TRUE(fs::exists(path)) << path << " is missing; run: cmake --build build --target refresh-glsl";
            EXPECT_TRUE(testing::readFile(path) == text) << path << " is stale; run: cmake --build build --target refresh-glsl";
        }
    }
    for (const auto& file : fs::directory_iterator("glsl"))
        EXPECT_TRUE(expectedFiles.count(file.path()) || file.path().filename() == "README.md")
            << file.path() << " comes from no shader of " << testing::kManifest;
}

} // namespace
} // namespace iblkit::compiler
