// The recipes' names, the documents' recipe as the documents read their maps, and the level from
// which the maps leave the lights out.
#include "shading/shading_recipe.hpp"

#include <gtest/gtest.h>

#include <set>

namespace iblkit::shading {
namespace {

TEST(ShadingRecipe, TheDocumentsRecipeIsTheDocumentsCombine) {
    const auto& recipe = documentRecipe();
    EXPECT_EQ(recipe.weighting, LobeWeighting::NdotL);
    EXPECT_EQ(recipe.mapping, LodMapping::Linear);
    EXPECT_EQ(recipe.direction, LookupDirection::Reflected);
    EXPECT_EQ(recipe.lookup, LookupLobe::Roughness);
    EXPECT_FALSE(recipe.lights);
}

TEST(ShadingRecipe, EveryRecipeHasItsOwnNameAndIsFoundByIt) {
    std::set<std::string> names;
    for (const auto& recipe : benchRecipes()) {
        EXPECT_TRUE(names.insert(recipe.name).second) << recipe.name;
        EXPECT_EQ(&recipeNamed(recipe.name), &recipe);
    }
    EXPECT_EQ(&benchRecipes()[0], &defaultRecipe());
    EXPECT_THROW(recipeNamed("nonsense"), std::invalid_argument);
}

TEST(ShadingRecipe, TheMapsKeepTheLightsOnlyWhereTheLobeIsNarrowerThanThem) {
    EnvironmentLight sun;
    sun.angularRadius = 0.044; // the built-in sky's 2.5-degree sun
    auto recipe = defaultRecipe();
    const MipSchedule schedule{LodMapping::Linear, 1, 6, 256};
    EXPECT_EQ(lightLevelOf(recipe, schedule, {}), 0u);
    EXPECT_EQ(lightLevelOf(recipe, schedule, {sun}), 0u) << "the default adds the lights at every roughness";
    recipe.lobeOverLight = 1;
    EXPECT_EQ(lightLevelOf(recipe, schedule, {sun}), 2u) << "mip 1's α = 0.04 is narrower than 0.044; mip 2's 0.16 is not";
    sun.angularRadius = 2;
    EXPECT_EQ(lightLevelOf(recipe, schedule, {sun}), 6u) << "no mip is as wide";
}

} // namespace
} // namespace iblkit::shading
