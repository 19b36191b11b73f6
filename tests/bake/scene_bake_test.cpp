// `bake --scene`: only what the scene's materials need is computed; a mip no material reads is
// the source's own, a skipped output is no file, and what is needed is what a full bake makes.
#include "bake.hpp"
#include "files.hpp"
#include "ktx2.hpp"
#include "scene_error.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace iblkit::bake {
namespace {

namespace fs = std::filesystem;

std::vector<float> ktx2Values(const fs::path& path) {
    const auto bytes = image_io::readFileBytes(path);
    return image_io::textureValues(image_io::decodeKtx2(bytes, path.string()));
}

nlohmann::json manifestOf(const fs::path& folder) {
    std::ifstream stream(folder / "manifest.json");
    return nlohmann::json::parse(stream);
}

// The built-in sky at 64² (4 mips at the kit's roughness 0, 0.19, 0.44, 1), with or without a scene.
class SceneBake : public ::testing::Test {
protected:
    fs::path bake(const std::string& name, const std::optional<std::string>& sceneMaterials) const {
        BakeSettings settings;
        settings.outputDir = scratch.path() / name;
        settings.size = 64;
        settings.lutSize = 16;
        settings.irradianceSize = 8;
        if (sceneMaterials)
            settings.scene = scratch.write(name + ".gltf", R"({"asset": {"version": "2.0"}, "materials": [)" +
                                                               *sceneMaterials + "]}");
        BakeProgress progress(true);
        bakeEnvironment(settings, "test", progress);
        return settings.outputDir;
    }
    static size_t mipOffset(uint32_t mip) {
        size_t offset = 0;
        for (uint32_t m = 0; m < mip; ++m) offset += size_t(6) * (64 >> m) * (64 >> m) * 4;
        return offset;
    }
    iblkit::testing::TempFolder scratch;
};

TEST_F(SceneBake, ARoughSceneFillsTheSharpMipAndBakesTheRestAsAFullBakeDoes) {
    const auto full = bake("full", std::nullopt);
    const auto rough = bake("rough", R"({"pbrMetallicRoughness": {"metallicFactor": 0, "roughnessFactor": 0.9}})");
    const auto fullSpecular = ktx2Values(full / "specular.ktx2"), roughSpecular = ktx2Values(rough / "specular.ktx2");
    ASSERT_EQ(fullSpecular.size(), roughSpecular.size()) << "every mip is there: the file stays loadable";
    // Mips 2 and 3 (roughness 0.44 and 1) are what a renderer reads for 0.9: bit for bit the full bake's.
    EXPECT_TRUE(std::equal(fullSpecular.begin() + mipOffset(2), fullSpecular.end(), roughSpecular.begin() + mipOffset(2)));
    // Mip 1 is read for no roughness of the scene: the source's own mip, sharper than the prefiltered one.
    EXPECT_FALSE(std::equal(fullSpecular.begin() + mipOffset(1), fullSpecular.begin() + mipOffset(2),
                            roughSpecular.begin() + mipOffset(1)));
    const auto manifest = manifestOf(rough);
    EXPECT_EQ(manifest.at("specular").at("filled_mips").at("mips"), nlohmann::json::array({1}));
    EXPECT_EQ(manifest.at("specular").at("prefiltered_mips"), nlohmann::json::array({0, 2, 3}));
    EXPECT_EQ(manifest.at("plan").at("outputs").at("irradiance"), true);
    EXPECT_FALSE(manifestOf(full).contains("plan"));
    EXPECT_FALSE(manifestOf(full).at("specular").contains("filled_mips"));
    EXPECT_EQ(ktx2Values(full / "irradiance.ktx2"), ktx2Values(rough / "irradiance.ktx2"));
    EXPECT_EQ(ktx2Values(full / "brdf_lut.ktx2"), ktx2Values(rough / "brdf_lut.ktx2"));
}

TEST_F(SceneBake, AnAllMetalSceneWritesNoIrradiance) {
    const auto metal = bake("metal", R"({"pbrMetallicRoughness": {"metallicFactor": 1, "roughnessFactor": 0.5}})");
    EXPECT_FALSE(fs::exists(metal / "irradiance.ktx2"));
    EXPECT_TRUE(fs::exists(metal / "specular.ktx2") && fs::exists(metal / "brdf_lut.ktx2"));
    const auto irradiance = manifestOf(metal).at("irradiance");
    EXPECT_TRUE(irradiance.at("file").is_null());
    EXPECT_TRUE(irradiance.contains("sh")) << "the SH coefficients cost nothing and stay";
}

TEST_F(SceneBake, AnUnlitSceneBakesNothingButItsPreview) {
    const auto unlit = bake("unlit", R"({"extensions": {"KHR_materials_unlit": {}}})");
    for (const char* file : {"specular.ktx2", "brdf_lut.ktx2", "irradiance.ktx2"}) EXPECT_FALSE(fs::exists(unlit / file)) << file;
    EXPECT_TRUE(fs::exists(unlit / "preview.png"));
    const auto manifest = manifestOf(unlit);
    for (const auto& file : manifest.at("files")) EXPECT_TRUE(fs::exists(unlit / file.at("name").get<std::string>()));
}

// glTF's roughness stops at 1: a factor of 1.5 once left every mip unfiltered. Clamped, it bakes
// the roughest mip as roughness 1 does, and the bake says so; --strict refuses it.
TEST_F(SceneBake, ARoughnessFactorPastOneBakesAsOneAndSaysSoOrIsRefusedWhenStrict) {
    const auto one = bake("one", R"({"pbrMetallicRoughness": {"metallicFactor": 1, "roughnessFactor": 1}})");
    BakeSettings settings;
    settings.outputDir = scratch.path() / "past-one";
    settings.size = 64;
    settings.lutSize = 16;
    settings.irradianceSize = 8;
    settings.scene = scratch.write("past-one.gltf", R"({"asset": {"version": "2.0"}, "materials": [
        {"name": "chrome", "pbrMetallicRoughness": {"metallicFactor": 1, "roughnessFactor": 1.5}}]})");
    BakeProgress progress(true);
    const auto summary = bakeEnvironment(settings, "test", progress);
    EXPECT_EQ(summary.sceneNotes, std::vector<std::string>{"chrome: roughnessFactor 1.5 is outside [0, 1]: clamped to 1"});
    EXPECT_EQ(manifestOf(settings.outputDir).at("specular").at("prefiltered_mips"), manifestOf(one).at("specular").at("prefiltered_mips"));
    EXPECT_EQ(ktx2Values(settings.outputDir / "specular.ktx2"), ktx2Values(one / "specular.ktx2"));
    settings.strict = true;
    settings.outputDir = scratch.path() / "strict";
    EXPECT_THROW(bakeEnvironment(settings, "test", progress), scene::SceneError);
    EXPECT_FALSE(fs::exists(settings.outputDir));
}

} // namespace
} // namespace iblkit::bake
