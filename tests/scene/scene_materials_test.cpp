// What each glTF material needs, from small scenes written here: factors, the texels of its
// metallicRoughness texture, unlit, clearcoat, transmission, volume, the default material, and
// the extensions the kit does not understand, listed.
#include "float_image.hpp"
#include "scene_error.hpp"
#include "scene_materials.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

namespace iblkit::scene {
namespace {

class SceneMaterials : public ::testing::Test {
protected:
    scene::SceneMaterials read(const std::string& materials, const std::string& rest = "") const {
        return readSceneMaterials(folder.write("scene.gltf", R"({"asset": {"version": "2.0"}, "materials": [)" + materials +
                                                                 "]" + rest + "}"));
    }
    std::string errorOf(const std::string& name, const std::string& text) const {
        try {
            readSceneMaterials(folder.write(name, text));
        } catch (const SceneError& error) {
            return error.what();
        }
        return "(no error)";
    }
    iblkit::testing::TempFolder folder;
};

TEST_F(SceneMaterials, FactorsGiveTheRangesOfAMaterialWithoutTextures) {
    const auto scene = read(R"({"name": "gold", "pbrMetallicRoughness": {"metallicFactor": 1, "roughnessFactor": 0.25}},
                               {"pbrMetallicRoughness": {}})");
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[0].name, "gold");
    EXPECT_EQ(scene.materials[0].roughness, ValueRange::of(0.25, 0.25));
    EXPECT_EQ(scene.materials[0].metalness, ValueRange::of(1, 1));
    EXPECT_EQ(scene.materials[1].name, "material 1");
    EXPECT_EQ(scene.materials[1].roughness, ValueRange::of(1, 1)) << "glTF's defaults: roughness 1, metalness 1";
    EXPECT_FALSE(scene.materials[0].unlit || scene.materials[0].transmission);
}

TEST_F(SceneMaterials, TheMetallicRoughnessTexturesTexelsScaleByTheFactors) {
    // Green is roughness, blue metalness: texels (g, b) = (51, 0), (204, 255), (102, 128), (153, 64).
    const std::vector<uint8_t> rgba{0, 51, 0, 255, 0, 204, 255, 255, 0, 102, 128, 255, 0, 153, 64, 255};
    image_io::writePng(folder.path() / "mr.png", 2, 2, rgba);
    const auto scene = read(R"({"pbrMetallicRoughness": {"metallicFactor": 0.5, "roughnessFactor": 0.5,
                                                          "metallicRoughnessTexture": {"index": 0}}})",
                            R"(, "textures": [{"source": 0}], "images": [{"uri": "mr.png"}])");
    const auto& material = scene.materials.at(0);
    EXPECT_DOUBLE_EQ(material.roughness.min, 0.5 * 51 / 255);
    EXPECT_DOUBLE_EQ(material.roughness.max, 0.5 * 204 / 255);
    EXPECT_DOUBLE_EQ(material.metalness.min, 0);
    EXPECT_DOUBLE_EQ(material.metalness.max, 0.5);
    EXPECT_TRUE(material.notes.empty());
}

TEST_F(SceneMaterials, AnImageTinygltfCannotDecodeIsAssumedToSpanItsWholeRange) {
    folder.write("mr.ktx2", std::string("\xABKTX 20\xBB\r\n\x1A\n", 12) + std::string(100, '\0'));
    const auto scene = read(R"({"pbrMetallicRoughness": {"roughnessFactor": 0.5, "metallicRoughnessTexture": {"index": 0}}})",
                            R"(, "textures": [{"source": 0}], "images": [{"uri": "mr.ktx2"}])");
    EXPECT_EQ(scene.materials.at(0).roughness, ValueRange::of(0, 0.5));
    ASSERT_FALSE(scene.materials.at(0).notes.empty());
}

TEST_F(SceneMaterials, ATextureWhoseTexelsCannotBeReadIsAssumedToSpanItsWholeRange) {
    const auto scene = read(R"({"pbrMetallicRoughness": {"roughnessFactor": 0.8, "metallicRoughnessTexture": {"index": 0}}})",
                            R"(, "textures": [{"extensions": {"KHR_texture_basisu": {"source": 0}}}],
                                 "images": [{"uri": "not-decoded.ktx2", "mimeType": "image/ktx2"}],
                                 "extensionsUsed": ["KHR_texture_basisu"])");
    const auto& material = scene.materials.at(0);
    EXPECT_EQ(material.roughness, ValueRange::of(0, 0.8));
    ASSERT_EQ(material.notes.size(), 2u) << "roughness and metalness";
    EXPECT_NE(material.notes[0].find("could not be read: [0, 0.8] is assumed"), std::string::npos) << material.notes[0];
}

TEST_F(SceneMaterials, ExtensionsChangeTheNeedsAndUnknownOnesAreListed) {
    const auto scene = read(R"({"name": "sign", "extensions": {"KHR_materials_unlit": {}}},
                               {"name": "car paint", "pbrMetallicRoughness": {"roughnessFactor": 0.6},
                                "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1, "clearcoatRoughnessFactor": 0.05}}},
                               {"name": "no clearcoat", "extensions": {"KHR_materials_clearcoat": {"clearcoatRoughnessFactor": 0.05}}},
                               {"name": "glass", "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1}}},
                               {"name": "jelly", "extensions": {"KHR_materials_volume": {}}},
                               {"name": "velvet", "extensions": {"KHR_materials_sheen": {}, "KHR_materials_ior": {"ior": 1.4}}})",
                            R"(, "extensionsUsed": ["KHR_materials_unlit", "KHR_materials_sheen", "KHR_materials_ior"])");
    const auto& m = scene.materials;
    ASSERT_EQ(m.size(), 6u);
    EXPECT_TRUE(m[0].unlit);
    EXPECT_EQ(m[1].clearcoatRoughness, ValueRange::of(0.05, 0.05));
    EXPECT_TRUE(m[2].clearcoatRoughness.empty()) << "a clearcoat factor of 0 is no clearcoat";
    EXPECT_TRUE(m[3].transmission);
    EXPECT_TRUE(m[4].transmission);
    EXPECT_EQ(m[5].unknownExtensions, std::vector<std::string>{"KHR_materials_sheen"});
    EXPECT_EQ(scene.unknownExtensions, std::vector<std::string>{"KHR_materials_sheen"});
}

TEST_F(SceneMaterials, APrimitiveWithoutAMaterialHasTheDefaultOne) {
    const auto scene = read(R"({"name": "used"})",
                            R"(, "meshes": [{"primitives": [{"attributes": {}, "material": 0}, {"attributes": {}}]}])");
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[1].name, "the default material");
    EXPECT_EQ(scene.materials[1].metalness, ValueRange::of(1, 1));
}

TEST_F(SceneMaterials, ABadSceneIsOneLineNamingTheFile) {
    EXPECT_EQ(errorOf("scene.obj", "o cube"), folder.path().string() + "/scene.obj: error: not a glTF scene (.gltf or .glb)");
    const auto broken = errorOf("broken.gltf", "{\"asset\": ");
    EXPECT_EQ(broken.find(folder.path().string() + "/broken.gltf: error: "), 0u) << broken;
    EXPECT_EQ(broken.find('\n'), std::string::npos) << broken;
    EXPECT_NE(errorOf("empty.glb", "").find("empty.glb: error: "), std::string::npos);
    EXPECT_THROW(
        try { readSceneMaterials(folder.path() / "missing.gltf"); } catch (const SceneError& error) {
            EXPECT_EQ(std::string(error.what()), (folder.path() / "missing.gltf").string() + ": error: no such scene file");
            throw;
        },
        SceneError);
}

} // namespace
} // namespace iblkit::scene
