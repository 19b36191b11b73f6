// What a bake writes for its shading recipe: the kit's (lights taken out, a G1 lobe, logarithmic
// mips) read back from its files, and the documents' made exactly as their steps make it.
#include "bake.hpp"
#include "bake_kernels.hpp"
#include "files.hpp"
#include "gpu_steps.hpp"
#include "ktx2.hpp"
#include "ktx2_validator.hpp"
#include "shading_maps.hpp"
#include "shading/built_lobe_tables.hpp"
#include "bake_error.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <unistd.h>

namespace iblkit::bake {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

BakeSettings smallBake(const fs::path& out) {
    BakeSettings settings;
    settings.outputDir = out;
    settings.size = 64;
    settings.lutSize = 32;
    settings.irradianceSize = 16;
    return settings;
}

json readJson(const fs::path& path) { return json::parse(std::ifstream(path)); }

// The built-in sky baked twice at 64², by the kit's recipe (the default) and by the documents'.
class RecipeBake : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        folder_ = fs::temp_directory_path() / ("iblkit-recipe-bake-" + std::to_string(::getpid()));
        fs::remove_all(folder_);
        BakeProgress quiet(true);
        bakeEnvironment(smallBake(kit()), "test", quiet);
        auto document = smallBake(folder_ / "document");
        document.recipe = "document";
        bakeEnvironment(document, "test", quiet);
    }
    static void TearDownTestSuite() { fs::remove_all(folder_); }
    static fs::path kit() { return folder_ / "kit"; }
    static fs::path document() { return folder_ / "document"; }
    static fs::path folder_;
};
fs::path RecipeBake::folder_;

TEST_F(RecipeBake, TheManifestRecordsTheRecipeAndEveryMipsRoughnessByItsSchedule) {
    const auto manifest = readJson(kit() / "manifest.json");
    const auto& shading = manifest.at("shading");
    EXPECT_EQ(shading.at("recipe"), "kit");
    EXPECT_EQ(shading.at("lobe_weighting"), "G1");
    EXPECT_EQ(shading.at("lod_mapping"), "logarithmic");
    const auto schedule = shading::scheduleOf(shading::defaultRecipe(), 4, 64); // 64² down to 8²
    ASSERT_EQ(shading.at("roughness").size(), 4u);
    for (uint32_t mip = 0; mip < 4; ++mip)
        EXPECT_FLOAT_EQ(shading.at("roughness")[mip].get<float>(), float(schedule.roughnessOf(mip))) << mip;
    EXPECT_EQ(manifest.at("specular").at("roughness"), shading.at("roughness"));
    EXPECT_EQ(shading.at("ibl_recipe").at("SpecularMips"), 4);
    EXPECT_EQ(shading.at("ibl_recipe").at("LightCount"), shading.at("lights").at("list").size());
    // The documents' recipe keeps their linear mips.
    const auto documentShading = readJson(document() / "manifest.json").at("shading");
    EXPECT_EQ(documentShading.at("recipe"), "document");
    for (uint32_t mip = 0; mip < 4; ++mip) EXPECT_EQ(documentShading.at("roughness")[mip].get<float>(), roughnessOfMip(mip, 4));
    EXPECT_TRUE(documentShading.at("lights").at("list").empty());
    EXPECT_FALSE(fs::exists(document() / "lights.gltf"));
    EXPECT_FALSE(fs::exists(document() / "lobe_table.ktx2"));
}

TEST_F(RecipeBake, TheSpecularKtx2CarriesTheSameRecordAsTheManifest) {
    const auto bytes = image_io::readFileBytes(kit() / "specular.ktx2");
    for (const auto& violation : iblkit::testing::validateKtx2(bytes)) ADD_FAILURE() << violation;
    const auto entries = image_io::decodeKtx2KeyValues(bytes, "specular.ktx2");
    ASSERT_TRUE(entries.count("iblkit.shading"));
    EXPECT_EQ(json::parse(entries.at("iblkit.shading")), readJson(kit() / "manifest.json").at("shading"));
    EXPECT_EQ(entries.at("KTXwriter"), "iblkit test");
}

TEST_F(RecipeBake, TheLobeTableFileHoldsTheTableTheShadingReads) {
    const auto bytes = image_io::readFileBytes(kit() / "lobe_table.ktx2");
    for (const auto& violation : iblkit::testing::validateKtx2(bytes)) ADD_FAILURE() << violation;
    const auto texture = image_io::decodeKtx2(bytes, "lobe_table.ktx2");
    EXPECT_EQ(texture.width, shading::kLobeTableSize);
    EXPECT_EQ(texture.format, image_io::PixelFormat::Rgba32Float);
    const auto table = shading::builtLobeTable(shading::LobeWeighting::G1);
    EXPECT_EQ(image_io::textureValues(texture), std::vector<float>(table.begin(), table.end()));
}

// The sky's sun leaves the maps and becomes one light: what the residual's SH lost is the
// light's radiance times its solid angle, exactly (the extraction moves energy, never makes it).
TEST_F(RecipeBake, TheSunIsTakenOutAsALightCarryingTheEnergyTheMapsLost) {
    const auto kitManifest = readJson(kit() / "manifest.json"), documentManifest = readJson(document() / "manifest.json");
    const auto& lights = kitManifest.at("shading").at("lights").at("list");
    ASSERT_EQ(lights.size(), 1u);
    const auto& light = lights[0];
    EXPECT_GT(light.at("share_of_the_light").get<double>(), 0.5);
    EXPECT_LT(light.at("angular_radius").get<double>(), shading::ExtractionSettings{}.maxRadius);
    const double y00 = 0.282094791773878;
    for (int c = 0; c < 3; ++c) {
        const double full = documentManifest.at("irradiance").at("sh").at("radiance")[0][c];
        const double residual = kitManifest.at("irradiance").at("sh").at("radiance")[0][c];
        const double carried = light.at("radiance")[c].get<double>() * light.at("solid_angle").get<double>() * y00;
        // 1e-4: the SH projection sums 6 × 16² texels of the 16² mip in float on the device.
        EXPECT_NEAR(residual + carried, full, 1e-4 * full) << "channel " << c;
    }
}

// lights.gltf as a glTF reader sees it: one directional KHR_lights_punctual light whose node's
// -Z runs from the sun towards the scene, of illuminance radiance × solid angle.
TEST_F(RecipeBake, LightsGltfHoldsTheSunAsAPunctualDirectionalLight) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadASCIIFromFile(&model, &error, &warning, (kit() / "lights.gltf").string())) << error;
    EXPECT_TRUE(warning.empty()) << warning;
    ASSERT_EQ(model.lights.size(), 1u);
    ASSERT_EQ(model.nodes.size(), 1u);
    const auto& light = model.lights[0];
    EXPECT_EQ(light.type, "directional");
    const auto manifestLight = readJson(kit() / "manifest.json").at("shading").at("lights").at("list")[0];
    const double solidAngle = manifestLight.at("solid_angle");
    for (int c = 0; c < 3; ++c) {
        EXPECT_LE(light.color[c], 1.0);
        EXPECT_NEAR(light.color[c] * light.intensity, manifestLight.at("radiance")[c].get<double>() * solidAngle,
                    1e-9 * light.intensity);
    }
    const auto& node = model.nodes[0];
    ASSERT_EQ(node.rotation.size(), 4u);
    const glm::dquat rotation(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    const glm::dvec3 shines = rotation * glm::dvec3(0, 0, -1);
    const auto& towards = manifestLight.at("direction");
    const glm::dvec3 direction(towards[0].get<double>(), towards[1].get<double>(), towards[2].get<double>());
    EXPECT_NEAR(glm::dot(shines, -direction), 1.0, 1e-12);
    ASSERT_TRUE(node.extensions.count("KHR_lights_punctual"));
    EXPECT_EQ(node.extensions.at("KHR_lights_punctual").Get("light").GetNumberAsInt(), 0);
}

// The documents' recipe is their maps, made as their steps make them: the source cube, mip m
// prefiltered by their lobe at m / (mips - 1), the irradiance of the whole environment.
TEST_F(RecipeBake, TheDocumentsRecipeIsTheirStepsBitForBit) {
    const auto settings = smallBake(document());
    const vulkan::VulkanContext context(settings.context);
    BakeKernels kernels(context, resolveSettings(settings));
    BakeProgress quiet(true);
    EnvironmentInput builtIn;
    auto source = buildSourceCube(context, builtIn, 64, quiet);
    SpecularLevels levels;
    for (uint32_t mip = 0; mip < 4; ++mip) levels.roughness.push_back(roughnessOfMip(mip, 4));
    auto specular = prefilterLevels(context, source, levels, kernels.specular(), quiet);
    const auto texture = image_io::decodeKtx2(image_io::readFileBytes(document() / "specular.ktx2"), "specular.ktx2");
    const auto expected = image_io::textureValues(image_io::makeTexture(image_io::PixelFormat::Rgba16Float, 64, 64, 6, 4,
                                                                        specular.download(context)));
    EXPECT_EQ(image_io::textureValues(texture), expected);
}

TEST(RecipeSettings, AnUnknownRecipeOrALobeTheMethodCannotPrefilterIsRefused) {
    BakeSettings settings = smallBake("out");
    settings.recipe = "cubic";
    EXPECT_THROW(resolveSettings(settings), BakeError);
    settings.recipe = "kit";
    settings.specularMethod = "table";
    try {
        resolveSettings(settings);
        ADD_FAILURE() << "a G1 lobe by the sample table";
    } catch (const BakeError& error) {
        EXPECT_NE(std::string(error.what()).find("--method convolution"), std::string::npos) << error.what();
    }
    settings.recipe.reset(); // every other method defaults to the documents' recipe
    EXPECT_NO_THROW(resolveSettings(settings));
    EXPECT_EQ(resolveSettings(settings).shadingRecipe->name, "document");
    settings.specularMethod = "convolution";
    EXPECT_EQ(resolveSettings(settings).shadingRecipe->name, "kit");
}

} // namespace
} // namespace iblkit::bake
