#include "gltf_shape.hpp"

#include "scene_error.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <regex>

namespace iblkit::scene {
namespace {

using nlohmann::json;

class ShapeCheck {
public:
    ShapeCheck(const json& gltf, const std::filesystem::path& file) : gltf_(gltf), file_(file) {}

    void all() {
        if (!gltf_.is_object()) fail("the file", "is not a JSON object");
        version();
        const auto materials = arrayOfObjects("materials");
        const auto textures = arrayOfObjects("textures");
        const auto images = arrayOfObjects("images");
        for (size_t i = 0; i < materials; ++i) material(gltf_["materials"][i], fmt::format("materials[{}]", i), textures);
        for (size_t i = 0; i < textures; ++i)
            index(gltf_["textures"][i], "source", fmt::format("textures[{}]", i), images, "images");
        meshes(materials);
    }

private:
    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw SceneError(fmt::format("{}: error: {} {}", file_.string(), where, what));
    }

    static std::string kindOf(const json& value) {
        if (value.is_string()) return "a string";
        if (value.is_boolean()) return "a boolean";
        if (value.is_null()) return "null";
        if (value.is_array()) return "an array";
        if (value.is_object()) return "an object";
        return "a number";
    }

    void version() const {
        if (!gltf_.contains("asset") || !gltf_["asset"].is_object()) fail("asset", "is missing or not an object");
        const auto& version = gltf_["asset"].value("version", json());
        if (!version.is_string()) fail("asset.version", "is " + kindOf(version) + ", not a string");
        static const std::regex twoDotX("2\\.[0-9]+");
        if (!std::regex_match(version.get<std::string>(), twoDotX))
            fail("asset.version", fmt::format("\"{}\" is not 2.x: the kit reads glTF 2.0", version.get<std::string>()));
    }

    // The length of gltf[name], which must be an array of objects when present.
    size_t arrayOfObjects(const char* name) const {
        if (!gltf_.contains(name)) return 0;
        const auto& array = gltf_[name];
        if (!array.is_array()) fail(name, "is " + kindOf(array) + ", not an array");
        for (size_t i = 0; i < array.size(); ++i)
            if (!array[i].is_object()) fail(fmt::format("{}[{}]", name, i), "is " + kindOf(array[i]) + ", not an object");
        return array.size();
    }

    const json* objectAt(const json& parent, const char* key, const std::string& where) const {
        if (!parent.contains(key)) return nullptr;
        if (!parent[key].is_object()) fail(where + "." + key, "is " + kindOf(parent[key]) + ", not an object");
        return &parent[key];
    }

    void number(const json& parent, const char* key, const std::string& where) const {
        if (parent.contains(key) && !parent[key].is_number())
            fail(where + "." + key, "is " + kindOf(parent[key]) + ", not a number");
    }

    void index(const json& parent, const char* key, const std::string& where, size_t count, const char* array) const {
        if (!parent.contains(key)) return;
        const auto& value = parent[key];
        if (!value.is_number_integer()) fail(where + "." + key, "is " + kindOf(value) + ", not an index");
        const auto at = value.get<int64_t>();
        if (at < 0 || uint64_t(at) >= count)
            fail(where + "." + key, fmt::format("{} is outside {} ({} of them)", at, array, count));
    }

    void material(const json& material, const std::string& where, size_t textures) const {
        if (const auto* pbr = objectAt(material, "pbrMetallicRoughness", where)) {
            const auto inner = where + ".pbrMetallicRoughness";
            number(*pbr, "roughnessFactor", inner);
            number(*pbr, "metallicFactor", inner);
            if (pbr->contains("baseColorFactor")) {
                const auto& colour = (*pbr)["baseColorFactor"];
                if (!colour.is_array() || colour.size() != 4 ||
                    !std::all_of(colour.begin(), colour.end(), [](const json& c) { return c.is_number(); }))
                    fail(inner + ".baseColorFactor", "is not an array of four numbers");
            }
            if (const auto* texture = objectAt(*pbr, "metallicRoughnessTexture", inner))
                index(*texture, "index", inner + ".metallicRoughnessTexture", textures, "textures");
        }
        if (const auto* extensions = objectAt(material, "extensions", where)) {
            const auto inner = where + ".extensions";
            if (const auto* clearcoat = objectAt(*extensions, "KHR_materials_clearcoat", inner)) {
                number(*clearcoat, "clearcoatFactor", inner + ".KHR_materials_clearcoat");
                number(*clearcoat, "clearcoatRoughnessFactor", inner + ".KHR_materials_clearcoat");
            }
            if (const auto* transmission = objectAt(*extensions, "KHR_materials_transmission", inner))
                number(*transmission, "transmissionFactor", inner + ".KHR_materials_transmission");
        }
    }

    void meshes(size_t materials) const {
        const auto count = arrayOfObjects("meshes");
        for (size_t m = 0; m < count; ++m) {
            const auto& mesh = gltf_["meshes"][m];
            const auto where = fmt::format("meshes[{}]", m);
            if (!mesh.contains("primitives")) continue;
            if (!mesh["primitives"].is_array()) fail(where + ".primitives", "is not an array");
            for (size_t p = 0; p < mesh["primitives"].size(); ++p) {
                const auto& primitive = mesh["primitives"][p];
                const auto inner = fmt::format("{}.primitives[{}]", where, p);
                if (!primitive.is_object()) fail(inner, "is not an object");
                index(primitive, "material", inner, materials, "materials");
            }
        }
    }

    const json& gltf_;
    const std::filesystem::path& file_;
};

} // namespace

void requireGltfShape(const json& gltf, const std::filesystem::path& file) {
    if (gltf.is_discarded()) return;
    ShapeCheck(gltf, file).all();
}

} // namespace iblkit::scene
