// judgeFeature on made-up outcomes: each way an outcome can differ from the manifest is named,
// and the status follows from the feature and the outcome.
#include "corpus_run.hpp"

#include <gtest/gtest.h>

namespace iblkit::porting {
namespace {

using compiler::CrossTarget;

ShaderOutcome compiledEverywhere() {
    ShaderOutcome shader;
    shader.name = "Shader.hlsl";
    for (const auto target : compiler::kCrossTargets) shader.forms[target] = {true, ""};
    shader.run = RunOutcome::Passed;
    return shader;
}

CorpusFeature plainFeature() {
    CorpusFeature feature;
    feature.id = "feature";
    feature.shader = "Shader.hlsl";
    return feature;
}

std::vector<std::string> mismatchesOf(const CorpusFeature& feature, const ShaderOutcome& shader) {
    return judgeFeature(feature, shader).mismatches;
}

using Lines = std::vector<std::string>;

TEST(FeatureJudging, AShaderThatCompilesEverywhereAndRunsIsSupported) {
    const auto outcome = judgeFeature(plainFeature(), compiledEverywhere());
    EXPECT_TRUE(outcome.mismatches.empty());
    EXPECT_EQ(outcome.status, FeatureStatus::Supported);
}

TEST(FeatureJudging, ALoweredFeatureNeedsItsEdit) {
    auto feature = plainFeature();
    feature.kitEdits = {"texel-widening"};
    auto shader = compiledEverywhere();
    EXPECT_EQ(mismatchesOf(feature, shader), Lines{"the kit's edit 'texel-widening' did not happen"});
    shader.kitEdits = {"texel-widening"};
    const auto outcome = judgeFeature(feature, shader);
    EXPECT_TRUE(outcome.mismatches.empty());
    EXPECT_EQ(outcome.status, FeatureStatus::Lowered);
}

TEST(FeatureJudging, AFormRefusedOrProducedAgainstTheManifestIsNamed) {
    auto feature = plainFeature();
    auto shader = compiledEverywhere();
    shader.forms[CrossTarget::Glsl] = {false, "glsl cannot express the shader"};
    EXPECT_EQ(mismatchesOf(feature, shader), Lines{"glsl was refused: glsl cannot express the shader"});
    feature.refusedForms = {CrossTarget::Glsl};
    EXPECT_TRUE(mismatchesOf(feature, shader).empty());
    feature.refusedForms.insert(CrossTarget::Essl);
    EXPECT_EQ(mismatchesOf(feature, shader), Lines{"essl was produced, but the manifest says it is refused"});
}

TEST(FeatureJudging, AFormThatDoesNotReadBackIsNamedUnlessTheManifestSaysSo) {
    auto feature = plainFeature();
    auto shader = compiledEverywhere();
    shader.forms[CrossTarget::Hlsl] = {true, "round_trip.hlsl:3:1: error: ..."};
    EXPECT_EQ(mismatchesOf(feature, shader), Lines{"hlsl does not read back: round_trip.hlsl:3:1: error: ..."});
    feature.unreadForms = {CrossTarget::Hlsl};
    EXPECT_TRUE(mismatchesOf(feature, shader).empty());
    EXPECT_EQ(mismatchesOf(feature, compiledEverywhere()), Lines{"hlsl reads back, but the manifest says it does not"});
}

TEST(FeatureJudging, ARunThatFailsIsNamedWithWhatItPrinted) {
    auto shader = compiledEverywhere();
    shader.run = RunOutcome::Failed;
    shader.runLog = "FAIL Out: 1 outside";
    EXPECT_EQ(mismatchesOf(plainFeature(), shader), Lines{"its run file failed: FAIL Out: 1 outside"});
}

TEST(FeatureJudging, ARefusalMustSayTheManifestsWords) {
    auto feature = plainFeature();
    ShaderOutcome shader;
    shader.compileError = "Shader.hlsl:2:1: error: a template cannot be lowered";
    EXPECT_EQ(mismatchesOf(feature, shader), Lines{"it was refused: Shader.hlsl:2:1: error: a template cannot be lowered"});
    feature.error = "a template";
    const auto outcome = judgeFeature(feature, shader);
    EXPECT_TRUE(outcome.mismatches.empty());
    EXPECT_EQ(outcome.status, FeatureStatus::Refused);
    feature.error = "operator overloading";
    EXPECT_EQ(mismatchesOf(feature, shader),
              Lines{"its error does not say 'operator overloading': Shader.hlsl:2:1: error: a template cannot be lowered"});
    EXPECT_EQ(mismatchesOf(feature, compiledEverywhere()), Lines{"it compiled, but the manifest says it is refused"});
}

TEST(FeatureJudging, AWarnedFeatureNeedsItsWarning) {
    auto feature = plainFeature();
    feature.warning = "is not honoured";
    auto shader = compiledEverywhere();
    EXPECT_EQ(mismatchesOf(feature, shader), Lines{"no warning says 'is not honoured'"});
    shader.warnings = {"Shader.hlsl:1:3: warning: [[vk::x]] is not honoured by the kit"};
    const auto outcome = judgeFeature(feature, shader);
    EXPECT_TRUE(outcome.mismatches.empty());
    EXPECT_EQ(outcome.status, FeatureStatus::Warned);
}

} // namespace
} // namespace iblkit::porting
