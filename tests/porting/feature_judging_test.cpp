// judgeFeature on made-up outcomes: each way an outcome can differ from the manifest is named,
// and the status follows from the outcome and the feature.
#include "corpus_run.hpp"

#include <gtest/gtest.h>

namespace iblkit::porting {
namespace {

using compiler::CrossTarget;

ShaderOutcome compiledEverywhere() {
    ShaderOutcome shader;
    shader.name = "Shader.hlsl";
    for (const auto target : compiler::kCrossTargets) shader.forms[target] = {true, target != CrossTarget::Msl, ""};
    shader.run = RunOutcome::Passed;
    return shader;
}

CorpusFeature plainFeature() {
    CorpusFeature feature;
    feature.id = "feature";
    feature.shader = "Shader.hlsl";
    return feature;
}

TEST(FeatureJudging, AShaderThatCompilesEverywhereAndRunsIsSupported) {
    const auto outcome = judgeFeature(plainFeature(), compiledEverywhere());
    EXPECT_TRUE(outcome.mismatches.empty());
    EXPECT_EQ(outcome.status, FeatureStatus::Supported);
}

TEST(FeatureJudging, AFeatureOfTheKitsEditsIsLoweredOnlyWhenTheEditHappened) {
    auto feature = plainFeature();
    feature.kitEdits = {"texel-widening"};
    auto shader = compiledEverywhere();
    ASSERT_EQ(judgeFeature(feature, shader).mismatches.size(), 1u) << "the edit did not happen";
    shader.kitEdits = {"texel-widening"};
    const auto outcome = judgeFeature(feature, shader);
    EXPECT_TRUE(outcome.mismatches.empty());
    EXPECT_EQ(outcome.status, FeatureStatus::Lowered);
}

TEST(FeatureJudging, AFormRefusedOrProducedAgainstTheManifestIsAMismatch) {
    auto feature = plainFeature();
    auto shader = compiledEverywhere();
    shader.forms[CrossTarget::Glsl] = {false, false, "glsl cannot express the shader"};
    EXPECT_EQ(judgeFeature(feature, shader).mismatches.size(), 1u);
    feature.refusedForms = {CrossTarget::Glsl};
    EXPECT_TRUE(judgeFeature(feature, shader).mismatches.empty());
    feature.refusedForms.insert(CrossTarget::Essl);
    EXPECT_EQ(judgeFeature(feature, shader).mismatches.size(), 1u) << "essl was produced";
}

TEST(FeatureJudging, AFormThatDoesNotReadBackOrARunThatFailsIsAMismatch) {
    auto shader = compiledEverywhere();
    shader.forms[CrossTarget::Hlsl] = {true, false, "round_trip.hlsl:3:1: error: ..."};
    EXPECT_EQ(judgeFeature(plainFeature(), shader).mismatches.size(), 1u);
    shader = compiledEverywhere();
    shader.run = RunOutcome::Failed;
    EXPECT_EQ(judgeFeature(plainFeature(), shader).mismatches.size(), 1u);
}

TEST(FeatureJudging, ARefusalMustSayTheManifestsWords) {
    auto feature = plainFeature();
    ShaderOutcome shader;
    shader.compileError = "Shader.hlsl:2:1: error: a template cannot be lowered";
    EXPECT_EQ(judgeFeature(feature, shader).mismatches.size(), 1u) << "refused, but the manifest says it compiles";
    feature.error = "a template";
    const auto outcome = judgeFeature(feature, shader);
    EXPECT_TRUE(outcome.mismatches.empty());
    EXPECT_EQ(outcome.status, FeatureStatus::Refused);
    feature.error = "operator overloading";
    EXPECT_EQ(judgeFeature(feature, shader).mismatches.size(), 1u);
    EXPECT_EQ(judgeFeature(feature, compiledEverywhere()).mismatches.size(), 1u) << "compiled, but should be refused";
}

TEST(FeatureJudging, AWarnedFeatureNeedsItsWarning) {
    auto feature = plainFeature();
    feature.warning = "is not honoured";
    auto shader = compiledEverywhere();
    EXPECT_EQ(judgeFeature(feature, shader).mismatches.size(), 1u);
    shader.warnings = {"Shader.hlsl:1:3: warning: [[vk::x]] is not honoured by the kit"};
    const auto outcome = judgeFeature(feature, shader);
    EXPECT_TRUE(outcome.mismatches.empty());
    EXPECT_EQ(outcome.status, FeatureStatus::Warned);
}

} // namespace
} // namespace iblkit::porting
