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
        const auto forms = crossCompileForms(shader, {CrossTarget::Glsl, CrossTarget::Essl, CrossTarget::Msl});
        std::map<fs::path, std::string> files;
        for (const auto& [target, form] : forms.produced) files["glsl/" + entry.name + extensions.at(target)] = form.source;
        files["glsl/" + entry.name + ".json"] = reflectionJson(shader, forms.produced, forms.refused);
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
