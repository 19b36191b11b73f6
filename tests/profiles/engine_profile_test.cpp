// The profile table: each engine's recipe exists and finds its mips by the engine's own formula.
#include "profiles/engine_profile.hpp"
#include "shading/shading_recipe.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace iblkit::profiles {
namespace {

TEST(EngineProfile, TheKitsProfileIsTheDefaultAndKeepsTheKitsRecipeAndFrame) {
    EXPECT_EQ(defaultProfile().name, "iblkit");
    EXPECT_EQ(defaultProfile().recipe, shading::defaultRecipe().name);
    EXPECT_EQ(defaultProfile().frame, CubeFrame::Kit);
}

TEST(EngineProfile, EveryProfileNamesARecipeOfTheBench) {
    for (const auto& profile : engineProfiles()) EXPECT_NO_THROW(shading::recipeNamed(profile.recipe)) << profile.name;
}

TEST(EngineProfile, ThreeJsReadsMipsByItsRoughnessToMip) {
    // three.js r187, envmap_common_pars_fragment: ENVMAP_MAX_LOD * r * (2 - r), and the shader's
    // lerp(R, N, r^4) (envmap_physical_pars_fragment), which is IBL_DIRECTION_FILAMENT.
    const auto& recipe = shading::recipeNamed(profileNamed("threejs").recipe);
    const auto schedule = shading::scheduleOf(recipe, 6, 256);
    for (double r : {0.0, 0.1, 0.25, 0.5, 0.75, 1.0}) EXPECT_NEAR(schedule.lodOf(r), 5 * r * (2 - r), 1e-12) << r;
    EXPECT_EQ(recipe.direction, shading::LookupDirection::Filament);
    EXPECT_EQ(recipe.lookup, shading::LookupLobe::Roughness);
    EXPECT_TRUE(recipe.lights.has_value()) << "the sun reaches three.js as a DirectionalLight";
    EXPECT_EQ(profileNamed("threejs").frame, CubeFrame::MirroredX);
}

TEST(EngineProfile, AnUnknownNameIsRefusedWithTheNames) {
    try {
        profileNamed("unity");
        FAIL() << "accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_EQ(std::string(error.what()), "no profile named 'unity' (there are: iblkit, threejs)");
    }
}

} // namespace
} // namespace iblkit::profiles
