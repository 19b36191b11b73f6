// What a bake computes for a scene's materials: the outputs, the specular mips between the
// neighbours of a used roughness, the LUT rows, and the estimates from the bench's curves.
#include "bake_plan.hpp"
#include "resolved_at.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <fstream>

namespace iblkit::bake {
namespace {

scene::MaterialNeeds material(double roughLow, double roughHigh, double metalLow, double metalHigh) {
    scene::MaterialNeeds needs;
    needs.name = "m";
    needs.roughness = scene::ValueRange::of(roughLow, roughHigh);
    needs.metalness = scene::ValueRange::of(metalLow, metalHigh);
    return needs;
}

BakeSettings documentRecipe() {
    BakeSettings settings; // 256², 6 mips at the documents' roughness 0, 0.2, ..., 1
    settings.recipe = "document";
    return settings;
}

BakePlan planFor(std::vector<scene::MaterialNeeds> materials, const BakeSettings& settings = documentRecipe()) {
    return planBake(resolvedAt(settings, 256), scene::SceneMaterials{"scene.gltf", std::move(materials), {}, {}});
}

std::vector<bool> neededMips(const BakePlan& plan) {
    std::vector<bool> needed;
    for (const auto& mip : plan.mips) needed.push_back(mip.needed);
    return needed;
}

TEST(BakePlan, WithoutASceneEverythingIsNeeded) {
    const auto plan = planBake(resolvedAt(BakeSettings{}, 256), std::nullopt);
    EXPECT_TRUE(plan.specular && plan.irradiance && plan.lut);
    EXPECT_EQ(neededMips(plan), std::vector<bool>(6, true));
    EXPECT_EQ(plan.lutFirstRow, 0u);
    EXPECT_EQ(plan.lutLastRow, 511u);
}

TEST(BakePlan, AnAllMetalSceneSkipsIrradiance) {
    const auto plan = planFor({material(0.05, 0.05, 1, 1), material(0.3, 0.3, 1, 1)});
    EXPECT_TRUE(plan.specular && plan.lut);
    EXPECT_FALSE(plan.irradiance);
    EXPECT_EQ(neededMips(plan), (std::vector<bool>{true, true, true, false, false, false}))
        << "0.05 and 0.3 lie between mips 0 and 2";
}

TEST(BakePlan, ARoughOnlySceneSkipsTheSharpMips) {
    const auto plan = planFor({material(0.7, 1.0, 0, 0)});
    EXPECT_TRUE(plan.irradiance);
    EXPECT_EQ(neededMips(plan), (std::vector<bool>{false, false, false, true, true, true}));
    EXPECT_EQ(neededMips(planFor({material(0.8, 1.0, 0, 0)})), (std::vector<bool>{false, false, false, false, true, true}))
        << "roughness 0.8 is mip 4's own: mip 3 is read only below it";
    EXPECT_TRUE(plan.mips[1].estimate.deviceMs > plan.mips[3].estimate.deviceMs) << "the skipped mips cost the most";
}

TEST(BakePlan, ARoughnessOnAMipNeedsThatMipAlone) {
    EXPECT_EQ(neededMips(planFor({material(0.4, 0.4, 0, 0)})), (std::vector<bool>{false, false, true, false, false, false}));
}

TEST(BakePlan, UnlitMaterialsNeedNothing) {
    auto unlit = material(0.5, 0.5, 0, 0);
    unlit.unlit = true;
    const auto plan = planFor({unlit});
    EXPECT_FALSE(plan.specular || plan.irradiance || plan.lut);
    EXPECT_EQ(neededMips(plan), std::vector<bool>(6, false));
    EXPECT_TRUE(plan.roughness.empty());
}

TEST(BakePlan, AClearcoatAddsItsRoughnessAndTheGapBetweenRangesIsSkipped) {
    auto coated = material(0.9, 0.9, 0, 0);
    coated.clearcoatRoughness = scene::ValueRange::of(0, 0);
    EXPECT_EQ(neededMips(planFor({coated})), (std::vector<bool>{true, false, false, false, true, true}))
        << "a mirror clearcoat reads mip 0 alone; roughness 0.9 reads mips 4 and 5";
}

TEST(BakePlan, TransmissionNeedsTheWholeChain) {
    auto glass = material(0.1, 0.1, 0, 0);
    glass.transmission = true;
    EXPECT_EQ(neededMips(planFor({glass})), std::vector<bool>(6, true));
}

TEST(BakePlan, TheLutRowsAreThoseBilinearReadsOfTheUsedRoughnessTouch) {
    const auto plan = planFor({material(0.25, 0.5, 1, 1)});
    // Row j holds roughness (j + 0.5) / 512: 0.25 lies between rows 127 and 128, 0.5 between 255 and 256.
    EXPECT_EQ(plan.lutFirstRow, 127u);
    EXPECT_EQ(plan.lutLastRow, 256u);
}

// The kit's recipe places its mips by its logarithmic schedule (256²: 0, 0.096, 0.173, 0.310,
// 0.557, 1), and a material reads the mips between its range's neighbours.
TEST(BakePlan, TheKitsMipsFollowItsScheduleAndSoDoTheirBrackets) {
    const auto schedule = shading::scheduleOf(shading::defaultRecipe(), 6, 256);
    const auto plan = planFor({material(0.2, 0.3, 0, 0)}, BakeSettings{});
    EXPECT_EQ(plan.recipe->name, "kit");
    for (const auto& mip : plan.mips) EXPECT_FLOAT_EQ(mip.roughness, float(schedule.roughnessOf(mip.mip))) << mip.mip;
    EXPECT_EQ(neededMips(plan), (std::vector<bool>{false, false, true, true, false, false}))
        << "0.2 to 0.3 lies between mips 2 (0.173) and 3 (0.310)";
}

// The bench measured the documents' N·L lobe: the kit's G1 lobe has its time estimated, not its error.
TEST(BakePlan, TheKitsLobeHasNoErrorEstimateFromTheBench) {
    const auto plan = planBake(resolvedAt(BakeSettings{}, 256), std::nullopt);
    EXPECT_TRUE(plan.specularEstimate.deviceMs.has_value());
    EXPECT_FALSE(plan.specularEstimate.errorRms.has_value());
}

TEST(BakePlan, TheDefaultsEstimatesComeFromTheBenchsCurves) {
    const auto plan = planBake(resolvedAt(documentRecipe(), 256), std::nullopt);
    ASSERT_TRUE(plan.specularEstimate.deviceMs && plan.lutEstimate.deviceMs && plan.irradianceEstimate.deviceMs);
    EXPECT_GT(*plan.specularEstimate.deviceMs, 0);
    // The defaults' documented bounds (docs/bench.md): specular within 1 % RMS, the LUT within 1e-4.
    EXPECT_LT(*plan.specularEstimate.errorRms, 0.01);
    EXPECT_LT(*plan.lutEstimate.errorMax, 1e-4);
    for (const auto& mip : plan.mips) // mip 0 is the source copied: the bench measures no error of it
        EXPECT_TRUE(mip.mip == 0 || mip.estimate.errorRms.has_value()) << "mip " << mip.mip;
    BakeSettings unmeasured = documentRecipe();
    unmeasured.samples = 77;
    EXPECT_FALSE(planBake(resolvedAt(unmeasured, 256), std::nullopt).specularEstimate.deviceMs) << "no curve: no estimate";
}

TEST(BakePlan, AMipCountTheBenchDidNotMeasureHasNoSpecularErrorEstimate) {
    const auto plan = planBake(resolvedAt(documentRecipe(), 128), std::nullopt); // 5 mips at 0, .25, .5, .75, 1; the bench's are in fifths
    EXPECT_TRUE(plan.specularEstimate.deviceMs.has_value());
    EXPECT_FALSE(plan.specularEstimate.errorRms.has_value()) << "roughness 1's error alone would understate it";
}

TEST(BakePlan, TheBuiltInCurvesWereMeasuredAtTheSizesTheyAssume) {
    std::ifstream stream("docs/bench/results.json");
    const auto command = nlohmann::json::parse(stream).at("command").get<std::string>();
    const auto& curves = BenchCurves::builtIn();
    EXPECT_NE(command.find("--size " + std::to_string(curves.cubeSize()) + " "), std::string::npos) << command;
    EXPECT_NE(command.find("--lut-size " + std::to_string(curves.lutSize()) + " "), std::string::npos) << command;
    EXPECT_NE(command.find("--irradiance-size " + std::to_string(curves.irradianceSize()) + " "), std::string::npos) << command;
}

TEST(BakePlan, ItsJsonSaysWhatIsNeeded) {
    const auto json = planJson(planFor({material(0.8, 1.0, 1, 1)}));
    EXPECT_EQ(json.at("outputs").at("irradiance"), false);
    EXPECT_EQ(json.at("specular_mips").at(0).at("needed"), false);
    EXPECT_EQ(json.at("specular_mips").at(5).at("needed"), true);
    EXPECT_EQ(json.at("scene"), "scene.gltf");
}

} // namespace
} // namespace iblkit::bake
