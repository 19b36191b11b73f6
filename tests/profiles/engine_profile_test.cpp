// The profile table: each engine's recipe exists and finds its mips by the engine's own formula.
#include "profiles/engine_profile.hpp"
#include "shading/shading_recipe.hpp"

#include <gtest/gtest.h>

#include <cmath>
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

TEST(EngineProfile, BabylonReadsMipsByItsLodGenerationScaleOverTheFullChain) {
    // Babylon.js 9, pbrIBLFunctions and pbrBlockReflection: log2(size alphaG) * 0.8, alphaG = r²
    // (+ 0.0005, which the schedule leaves out), over every mip down to 1x1.
    const auto& profile = profileNamed("babylon");
    const auto& recipe = shading::recipeNamed(profile.recipe);
    const auto schedule = shading::scheduleOf(recipe, 9, 256);
    for (double r : {0.1, 0.25, 0.5, 0.75})
        EXPECT_NEAR(schedule.lodOf(r), 0.8 * std::log2(256 * r * r), 1e-12) << r;
    EXPECT_EQ(recipe.direction, shading::LookupDirection::Reflected);
    EXPECT_EQ(profile.lastMipSize, 1u);
    EXPECT_EQ(profile.frame, CubeFrame::MirroredZ);
    EXPECT_EQ(profile.file, SpecularFile::Dds);
}

TEST(EngineProfile, FilamentReadsTheKitsFrameByThreeJsMappingWithItsShaderSh) {
    // Filament 1.53: surface_light_indirect's lod = (levels - 1) r (2 - r) and lerp(R, N, α²),
    // as three.js; cubes sampled as they are; IndirectLight takes cmgen's --sh-shader SH.
    const auto& profile = profileNamed("filament");
    EXPECT_EQ(profile.recipe, profileNamed("threejs").recipe);
    EXPECT_EQ(profile.frame, CubeFrame::Kit);
    EXPECT_EQ(profile.file, SpecularFile::Ktx1);
    EXPECT_EQ(profile.shCoefficients, ShForm::IrradianceShader);
}

TEST(EngineProfile, TheGltfSampleViewerReadsMipsLinearlyDownTo16WithTheKitsLut) {
    // glTF-Sample-Renderer 1.1, ibl.glsl: lod = roughness (u_MipCount - 1), reflect(-v, n), the LUT
    // at (N·V, roughness); ibl_sampler.js stops its chain four levels short of 1x1.
    const auto& profile = profileNamed("gltf");
    const auto& recipe = shading::recipeNamed(profile.recipe);
    const auto schedule = shading::scheduleOf(recipe, 5, 256);
    for (double r : {0.0, 0.1, 0.25, 0.5, 0.75, 1.0}) EXPECT_NEAR(schedule.lodOf(r), 4 * r, 1e-12) << r;
    EXPECT_EQ(recipe.direction, shading::LookupDirection::Reflected);
    EXPECT_EQ(recipe.lookup, shading::LookupLobe::Roughness);
    EXPECT_EQ(profile.lastMipSize, 16u);
    EXPECT_EQ(profile.frame, CubeFrame::Kit);
    EXPECT_TRUE(profile.readsKitLut);
}

TEST(EngineProfile, TheRenderOfARecipeReadsTheChainOfTheProfileMadeForIt) {
    EXPECT_EQ(profileMadeFor("babylon-lights").name, "babylon");
    EXPECT_EQ(profileMadeFor("quadratic-lights").name, "threejs");
    EXPECT_EQ(profileMadeFor("linear-lights").name, "gltf");
    EXPECT_EQ(profileMadeFor("document").name, "iblkit") << "a recipe no engine reads takes the kit's chain";
}

TEST(EngineProfile, AnUnknownNameIsRefusedWithTheNames) {
    try {
        profileNamed("unity");
        FAIL() << "accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_EQ(std::string(error.what()), "no profile named 'unity' (there are: iblkit, threejs, babylon, filament, gltf)");
    }
}

} // namespace
} // namespace iblkit::profiles
