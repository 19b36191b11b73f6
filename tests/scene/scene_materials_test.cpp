// What each glTF material needs, from small scenes written here: factors, the texels of its
// metallicRoughness texture, unlit, clearcoat, transmission, volume, the default material, and
// the extensions the kit does not understand, listed; and the scenes and files it refuses.
#include "float_image.hpp"
#include "scene_error.hpp"
#include "scene_materials.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>

namespace iblkit::scene {
namespace {

namespace fs = std::filesystem;

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

// A roughness of 1.5 once asked for no prefiltered mip at all, and a negative one for mips the
// plan then called unneeded.
TEST_F(SceneMaterials, AFactorOutsideZeroToOneIsClampedWithANoteOrRefusedWhenStrict) {
    const std::string materials = R"({"name": "chrome", "pbrMetallicRoughness": {"roughnessFactor": 1.5, "metallicFactor": -0.5}},
                                     {"name": "coat", "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1,
                                                                                                "clearcoatRoughnessFactor": 1e30}}})";
    const auto scene = read(materials);
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[0].roughness, ValueRange::of(1, 1));
    EXPECT_EQ(scene.materials[0].metalness, ValueRange::of(0, 0));
    EXPECT_EQ(scene.materials[0].notes, (std::vector<std::string>{"roughnessFactor 1.5 is outside [0, 1]: clamped to 1",
                                                                  "metallicFactor -0.5 is outside [0, 1]: clamped to 0"}));
    EXPECT_EQ(scene.materials[1].clearcoatRoughness, ValueRange::of(1, 1));
    EXPECT_EQ(scene.materials[1].notes, std::vector<std::string>{"clearcoatRoughnessFactor 1e+30 is outside [0, 1]: clamped to 1"});
    const auto file = folder.write("strict.gltf", R"({"asset": {"version": "2.0"}, "materials": [)" + materials + "]}");
    try {
        readSceneMaterials(file, true);
        ADD_FAILURE() << "--strict took a roughness of 1.5";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()),
                  file.string() + ": error: chrome: roughnessFactor 1.5 is outside [0, 1] (--strict refuses it)");
    }
}

// tinygltf's parser recursed once a level: 20,000 nested arrays in `extras` overflowed the stack.
TEST_F(SceneMaterials, JsonNestedPastTheLimitIsRefusedInTheGltfAndInTheGlb) {
    const std::string json = R"({"asset": {"version": "2.0"}, "extras": )" + std::string(20000, '[') + std::string(20000, ']') + "}";
    const std::string expected = "its JSON nests arrays and objects more than 256 deep";
    const auto gltf = errorOf("deep.gltf", json);
    EXPECT_EQ(gltf, (folder.path() / "deep.gltf").string() + ": error: " + expected);
    std::string chunk = json;
    while (chunk.size() % 4) chunk += ' ';
    const auto word = [](uint32_t value) { return std::string{char(value), char(value >> 8), char(value >> 16), char(value >> 24)}; };
    const std::string glb = "glTF" + word(2) + word(uint32_t(20 + chunk.size())) + word(uint32_t(chunk.size())) + "JSON" + chunk;
    EXPECT_EQ(errorOf("deep.glb", glb), (folder.path() / "deep.glb").string() + ": error: " + expected);
    EXPECT_EQ(read("{}", R"(, "extras": )" + std::string(200, '[') + std::string(200, ']')).materials.size(), 1u)
        << "200 levels are within the limit";
}

// A folder once came back as std::bad_alloc and a FIFO waited forever for a writer: each is
// refused, naming the file the scene names.
TEST_F(SceneMaterials, AFileTheSceneNamesMustBeARegularFile) {
    fs::create_directories(folder.path() / "folder.bin");
    ASSERT_EQ(::mkfifo((folder.path() / "fifo.png").c_str(), 0600), 0);
    for (const auto& [uri, kind, why] : {std::tuple{std::string("folder.bin"), "buffers", "Is a directory"},
                                         std::tuple{std::string("fifo.png"), "images", "not a regular file (a device, a pipe or a socket)"}}) {
        const std::string entry = std::string(kind) == "buffers" ? R"({"uri": ")" + uri + R"(", "byteLength": 4})"
                                                                 : R"({"uri": ")" + uri + R"("})";
        const auto error = errorOf("names.gltf", R"({"asset": {"version": "2.0"}, ")" + std::string(kind) + R"(": [)" + entry + "]}");
        EXPECT_EQ(error.find((folder.path() / "names.gltf").string() + ": error: "), 0u) << error;
        EXPECT_NE(error.find("cannot open '" + (folder.path() / uri).string() + "': " + why), std::string::npos) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
}

// The lighting's needs read materials and textures, never geometry: a missing buffer of vertices
// is a note (tinygltf refused the whole scene with "File not found : mesh.bin"), and a missing
// buffer that an image lies in is refused in the kit's words.
TEST_F(SceneMaterials, AMissingGeometryBufferIsANoteAndAMissingImageBufferIsRefused) {
    const std::string geometry = R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "mesh.bin", "byteLength": 36}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"roughnessFactor": 0.5, "metallicFactor": 0}}]})";
    const auto scene = readSceneMaterials(folder.write("geometry.gltf", geometry));
    ASSERT_EQ(scene.notes.size(), 1u);
    EXPECT_EQ(scene.notes[0], "buffer 'mesh.bin' is missing; it holds only geometry, which the lighting's needs do not read");
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].roughness.max, 0.5);
    const auto image = errorOf("image.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "pixels.bin", "byteLength": 36}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}], "images": [{"bufferView": 0, "mimeType": "image/png"}],
        "textures": [{"source": 0}],
        "materials": [{"pbrMetallicRoughness": {"metallicRoughnessTexture": {"index": 0}}}]})");
    EXPECT_EQ(image, (folder.path() / "image.gltf").string() + ": error: cannot open '" + (folder.path() / "pixels.bin").string() +
                         "': No such file or directory");
}

// tinygltf read each of these without a word: a factor it could not read became the default, a
// material index out of range was dropped, and any version passed.
TEST_F(SceneMaterials, MalformedGltfIsRefusedInOneLineNamingWhereAndWhat) {
    const std::string asset = R"("asset": {"version": "2.0"})";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {R"({"asset": {"version": "1.0"}})", R"(asset.version "1.0" is not 2.x: the kit reads glTF 2.0)"},
        {R"({"asset": {"version": "3.0"}})", R"(asset.version "3.0" is not 2.x: the kit reads glTF 2.0)"},
        {"{" + asset + R"(, "materials": {}})", "materials is an object, not an array"},
        {"{" + asset + R"(, "materials": [{"pbrMetallicRoughness": {"roughnessFactor": "high"}}]})",
         "materials[0].pbrMetallicRoughness.roughnessFactor is a string, not a number"},
        {"{" + asset + R"(, "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1]}}]})",
         "materials[0].pbrMetallicRoughness.baseColorFactor is not an array of four numbers"},
        {"{" + asset + R"(, "materials": [{}], "meshes": [{"primitives": [{"attributes": {}, "material": 5}]}]})",
         "meshes[0].primitives[0].material 5 is outside materials (1 of them)"},
        {"{" + asset + R"(, "materials": [{"pbrMetallicRoughness": {"metallicRoughnessTexture": {"index": 3}}}]})",
         "materials[0].pbrMetallicRoughness.metallicRoughnessTexture.index 3 is outside textures (0 of them)"},
    };
    for (const auto& [text, expected] : cases) {
        const auto error = errorOf("malformed.gltf", text);
        EXPECT_EQ(error, (folder.path() / "malformed.gltf").string() + ": error: " + expected) << text;
    }
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
