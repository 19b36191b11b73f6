// hlsl/porting/ holds a shader for each porting feature, and corpus.json says what each feature
// must show. Each shader compiles (or is refused with the stated words), goes into every form,
// each form reads back with the compiler that reads it, a form is refused only where the
// manifest says so, and each run file passes on lavapipe with the validation layer on.
// docs/porting.md is what `iblkit porting` makes of the corpus.
#include "corpus_run.hpp"
#include "porting_error.hpp"
#include "run_process.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace iblkit::porting {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = "hlsl/porting";

const CorpusManifest& manifest() {
    static const CorpusManifest corpus = readCorpusManifest(kCorpus);
    return corpus;
}

// Called while the tests are registered, where an exception would end the program: a manifest
// that cannot be read gives no shaders here, and fails ItsManifestIsRead instead.
std::vector<std::string> shaderNames() {
    std::vector<std::string> names;
    try {
        for (const auto& shader : manifest().shaders) names.push_back(shader.name);
    } catch (const PortingError&) {
    }
    return names;
}

std::string readText(const fs::path& path) {
    std::ifstream stream(path, std::ios::binary);
    std::ostringstream text;
    text << stream.rdbuf();
    return text.str();
}

class PortingCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(PortingCorpus, EveryFeatureOfTheShaderIsAsTheManifestSays) {
    const auto& shaders = manifest().shaders;
    const auto shader = std::find_if(shaders.begin(), shaders.end(), [](const auto& s) { return s.name == GetParam(); });
    run::RunOptions options;
    options.validation = true;
    const auto outcome = runCorpusShader(*shader, options);
    for (const auto& feature : manifest().features) {
        if (feature.shader != GetParam()) continue;
        for (const auto& mismatch : judgeFeature(feature, outcome).mismatches) ADD_FAILURE() << feature.id << ": " << mismatch;
    }
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = fs::path(info.param).replace_extension().string();
    std::replace(name.begin(), name.end(), '/', '_');
    return name;
}

INSTANTIATE_TEST_SUITE_P(Shaders, PortingCorpus, ::testing::ValuesIn(shaderNames()), testName);

TEST(PortingCorpusFiles, ItsManifestIsRead) {
    EXPECT_NO_THROW(readCorpusManifest(kCorpus));
}

TEST(PortingCorpusFiles, EveryShaderInTheCorpusIsInTheManifest) {
    const auto names = shaderNames();
    for (const auto& entry : fs::recursive_directory_iterator(kCorpus)) {
        if (entry.path().extension() != ".hlsl") continue;
        const auto name = fs::relative(entry.path(), kCorpus).string();
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name << " is in no feature of corpus.json";
    }
}

TEST(PortingDoc, IsWhatThePortingCommandMakesOfTheCorpus) {
    testing::TempFolder folder;
    const auto out = folder.path() / "porting.md";
    const auto result = testing::runProcess({IBLKIT_EXECUTABLE, "porting", "--out", out.string()});
    ASSERT_EQ(result.exitCode, 0) << result.out << result.err;
    EXPECT_EQ(readText(out), readText("docs/porting.md"))
        << "docs/porting.md is stale: regenerate it with `iblkit porting --out docs/porting.md`";
}

} // namespace
} // namespace iblkit::porting
