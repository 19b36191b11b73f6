// `iblkit plan` as a user runs it: the plan of a scene, as text and as JSON, and one line for a
// scene it cannot read.
#include "run_process.hpp"
#include "temp_folder.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace iblkit::testing {
namespace {

const char* kMetalScene = R"({"asset": {"version": "2.0"}, "materials": [
    {"name": "chrome", "pbrMetallicRoughness": {"metallicFactor": 1, "roughnessFactor": 0.05}},
    {"name": "sign", "extensions": {"KHR_materials_unlit": {}}}],
  "extensionsUsed": ["KHR_materials_unlit", "KHR_materials_sheen"]})";

TEST(PlanCli, TheTextPlanSaysWhatIsSkippedAndWhy) {
    TempFolder folder;
    const auto scene = folder.write("metal.gltf", kMetalScene);
    const auto result = runProcess({IBLKIT_EXECUTABLE, "plan", scene.string()});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_NE(result.out.find("2 materials, 1 lit, 1 unlit"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("every lit material is all metal: no irradiance"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("irradiance  skipped"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("warning     the scene uses KHR_materials_sheen, which the kit does not understand"),
              std::string::npos)
        << result.out;
}

TEST(PlanCli, TheJsonPlanFollowsTheBakeSettings) {
    TempFolder folder;
    const auto scene = folder.write("metal.gltf", kMetalScene);
    const auto result = runProcess({IBLKIT_EXECUTABLE, "plan", scene.string(), "--size", "64", "--mips", "3", "--json"});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const auto plan = nlohmann::json::parse(result.out);
    ASSERT_EQ(plan.at("specular_mips").size(), 3u);
    EXPECT_EQ(plan.at("specular_mips").at(0).at("face_size"), 64);
    EXPECT_EQ(plan.at("specular_mips").at(0).at("needed"), true);
    EXPECT_EQ(plan.at("specular_mips").at(2).at("needed"), false) << "roughness 0.05 reads mips 0 and 1 of 0, 0.5, 1";
    EXPECT_EQ(plan.at("outputs").at("irradiance"), false);
}

TEST(PlanCli, ASceneItCannotReadIsOneLine) {
    TempFolder folder;
    const auto scene = folder.write("broken.gltf", "{\"asset\": ");
    const auto result = runProcess({IBLKIT_EXECUTABLE, "plan", scene.string()});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_EQ(result.err.rfind(scene.string() + ": error: ", 0), 0u) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    const auto badSetting = runProcess({IBLKIT_EXECUTABLE, "plan", folder.write("m.gltf", kMetalScene).string(), "--size", "100"});
    EXPECT_NE(badSetting.exitCode, 0);
    EXPECT_NE(badSetting.err.find("--size"), std::string::npos) << badSetting.err;
}

// The plan once planned for an environment the bake then refused.
TEST(PlanCli, AnEnvironmentTheBakeRefusesThePlanRefusesInOneLine) {
    TempFolder folder;
    const auto scene = folder.write("metal.gltf", kMetalScene).string();
    for (const auto& [environment, expected] :
         {std::pair{(folder.path() / "missing.hdr").string(), std::string("missing.hdr")},
          std::pair{folder.write("garbage.hdr", "not an image").string(), std::string("garbage.hdr")},
          std::pair{folder.path().string(), folder.path().filename().string()}}) {
        const auto result = runProcess({IBLKIT_EXECUTABLE, "plan", scene, environment});
        EXPECT_NE(result.exitCode, 0) << environment;
        EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_EQ(result.out, "") << environment;
    }
}

} // namespace
} // namespace iblkit::testing
