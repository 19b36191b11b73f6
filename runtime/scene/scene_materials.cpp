#include "scene_materials.hpp"

#include "gltf_shape.hpp"
#include "scene_error.hpp"
#include "scene_files.hpp"

#include <tiny_gltf.h>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <set>

namespace iblkit::scene {
namespace {

struct FactorCheck {
    const std::filesystem::path& file;
    bool strict;
};

// Extensions that change nothing image-based lighting needs: emission, the index of refraction
// and specular colour (the same lobes), texture transforms (the whole texture's range is kept),
// punctual lights, variants (every material is read), mesh quantization; and texture formats,
// whose texels are assumed to span [0, 1] when they cannot be read.
const std::set<std::string> kNeutralExtensions{
    "KHR_materials_emissive_strength", "KHR_materials_ior", "KHR_materials_specular", "KHR_texture_transform",
    "KHR_lights_punctual", "KHR_materials_variants", "KHR_mesh_quantization", "KHR_texture_basisu", "EXT_texture_webp"};
const std::set<std::string> kNeedsExtensions{"KHR_materials_unlit", "KHR_materials_clearcoat", "KHR_materials_transmission",
                                             "KHR_materials_volume"};

double numberOr(const tinygltf::Value& object, const char* key, double fallback) {
    if (!object.IsObject() || !object.Has(key)) return fallback;
    const auto& value = object.Get(key);
    return value.IsNumber() ? value.GetNumberAsDouble() : fallback;
}

int textureIndexOf(const tinygltf::Value& object, const char* key) {
    if (!object.IsObject() || !object.Has(key)) return -1;
    return int(numberOr(object.Get(key), "index", -1));
}

// The range of each channel of a texture's texels, normalised to [0, 1]; empty ranges when its
// texels cannot be read (a format tinygltf does not decode).
std::vector<ValueRange> channelRanges(const tinygltf::Model& model, int textureIndex) {
    if (textureIndex < 0 || size_t(textureIndex) >= model.textures.size()) return {};
    const int source = model.textures[textureIndex].source;
    if (source < 0 || size_t(source) >= model.images.size()) return {};
    const auto& image = model.images[source];
    const size_t bytes = image.bits / 8, channels = size_t(std::max(image.component, 0));
    if ((bytes != 1 && bytes != 2) || channels == 0 || image.image.size() < size_t(image.width) * image.height * channels * bytes)
        return {};
    const double scale = bytes == 1 ? 255.0 : 65535.0;
    std::vector<ValueRange> ranges(channels);
    for (size_t texel = 0; texel < size_t(image.width) * image.height; ++texel)
        for (size_t channel = 0; channel < channels; ++channel) {
            const unsigned char* at = image.image.data() + (texel * channels + channel) * bytes;
            const double value = bytes == 1 ? at[0] : double(at[0] | at[1] << 8);
            ranges[channel].include(value / scale);
        }
    return ranges;
}

// factor × the texture's channel over its texels; factor × [0, 1] (and a note) when the texels
// cannot be read.
ValueRange textured(const tinygltf::Model& model, int textureIndex, size_t channel, double factor, const char* what,
                    MaterialNeeds& needs) {
    if (textureIndex < 0) return ValueRange::of(factor, factor);
    const auto ranges = channelRanges(model, textureIndex);
    if (ranges.size() <= channel) {
        needs.notes.push_back(fmt::format("the texels of its {} texture (texture {}) could not be read: "
                                          "[0, {}] is assumed", what, textureIndex, factor));
        return ValueRange::of(0, factor);
    }
    return ValueRange::of(ranges[channel].min * factor, ranges[channel].max * factor);
}

// glTF's factors lie in [0, 1]. One outside is clamped into it, with a note naming it, or refused
// with `strict`: a roughness of 1.5 would otherwise ask for no prefiltered mip at all.
double factorIn01(double factor, const char* name, const FactorCheck& check, MaterialNeeds& needs) {
    if (factor >= 0 && factor <= 1) return factor;
    if (check.strict)
        throw SceneError(fmt::format("{}: error: {}: {} {} is outside [0, 1] (--strict refuses it)", check.file.string(),
                                     needs.name, name, factor));
    const double clamped = std::clamp(factor, 0.0, 1.0);
    needs.notes.push_back(fmt::format("{} {} is outside [0, 1]: clamped to {}", name, factor, clamped));
    return clamped;
}

MaterialNeeds needsOf(const tinygltf::Model& model, const tinygltf::Material& material, size_t index, const FactorCheck& check) {
    MaterialNeeds needs;
    needs.name = material.name.empty() ? fmt::format("material {}", index) : material.name;
    const auto& pbr = material.pbrMetallicRoughness;
    const int metallicRoughness = pbr.metallicRoughnessTexture.index;
    needs.roughness = textured(model, metallicRoughness, 1, factorIn01(pbr.roughnessFactor, "roughnessFactor", check, needs),
                               "metallicRoughness", needs);
    needs.metalness = textured(model, metallicRoughness, 2, factorIn01(pbr.metallicFactor, "metallicFactor", check, needs),
                               "metallicRoughness", needs);
    for (const auto& [name, value] : material.extensions) {
        if (name == "KHR_materials_unlit") needs.unlit = true;
        else if (name == "KHR_materials_clearcoat" && numberOr(value, "clearcoatFactor", 0) > 0)
            needs.clearcoatRoughness =
                textured(model, textureIndexOf(value, "clearcoatRoughnessTexture"), 1,
                         factorIn01(numberOr(value, "clearcoatRoughnessFactor", 0), "clearcoatRoughnessFactor", check, needs),
                         "clearcoatRoughness", needs);
        else if (name == "KHR_materials_transmission" && numberOr(value, "transmissionFactor", 0) > 0) needs.transmission = true;
        else if (name == "KHR_materials_volume") needs.transmission = true;
        else if (!isUnderstoodExtension(name)) needs.unknownExtensions.push_back(name);
    }
    return needs;
}

bool usesTheDefaultMaterial(const tinygltf::Model& model) {
    for (const auto& mesh : model.meshes)
        for (const auto& primitive : mesh.primitives)
            if (primitive.material < 0) return true;
    return false;
}

// tinygltf's image loader, except that an image it cannot decode (KTX2, WebP) is left without
// texels instead of failing the scene: its texture's range is then assumed (textured()).
bool loadImageOrLeaveEmpty(tinygltf::Image* image, const int index, std::string* error, std::string* warning, int width,
                           int height, const unsigned char* bytes, int size, void* user) {
    if (tinygltf::LoadImageData(image, index, error, warning, width, height, bytes, size, user)) return true;
    image->image.clear();
    if (error) error->clear();
    return true;
}

// The JSON of a .gltf, or the JSON chunk of a .glb (its header, then the chunk's length and type);
// empty when the container is too short to say, which tinygltf then reports.
std::string_view jsonOf(const std::vector<std::byte>& bytes, bool binary) {
    const auto text = std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (!binary) return text;
    if (bytes.size() < 20) return {};
    const auto byte = [&](size_t at) { return uint32_t(std::to_integer<unsigned char>(bytes[at])); };
    const uint32_t length = byte(12) | byte(13) << 8 | byte(14) << 16 | byte(15) << 24;
    return text.substr(20, length);
}

tinygltf::Model load(const std::filesystem::path& file, std::vector<std::string>& notes) {
    std::error_code error;
    if (!std::filesystem::exists(file, error)) throw SceneError(file.string() + ": error: no such scene file");
    const bool binary = file.extension() == ".glb";
    if (!binary && file.extension() != ".gltf")
        throw SceneError(file.string() + ": error: not a glTF scene (.gltf or .glb)");
    const auto bytes = readSceneFile(file);
    requireJsonNestingWithin(jsonOf(bytes, binary), file);
    // Parsed once, for the kit's checks; tinygltf parses it again, its own way.
    const auto gltf = nlohmann::json::parse(jsonOf(bytes, binary), nullptr, false);
    requireGltfShape(gltf, file);
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(loadImageOrLeaveEmpty, nullptr);
    auto geometry = geometryOnlyBuffers(gltf);
    readReferencedFilesByThePolicy(loader, geometry);
    tinygltf::Model model;
    std::string problem, warning;
    const auto folder = file.parent_path().string();
    bool loaded = false;
    try {
        loaded = binary ? loader.LoadBinaryFromMemory(&model, &problem, &warning,
                                                      reinterpret_cast<const unsigned char*>(bytes.data()), unsigned(bytes.size()),
                                                      folder)
                        : loader.LoadASCIIFromString(&model, &problem, &warning, reinterpret_cast<const char*>(bytes.data()),
                                                     unsigned(bytes.size()), folder);
    } catch (const ReferencedFileRefused& refused) {
        throw SceneError(file.string() + ": error: " + refused.what());
    }
    if (!loaded) {
        auto line = problem.empty() ? std::string("tinygltf could not read it") : problem;
        while (!line.empty() && (line.back() == '\n' || line.back() == ' ')) line.pop_back();
        std::replace(line.begin(), line.end(), '\n', ' ');
        throw SceneError(file.string() + ": error: " + line);
    }
    for (const auto& uri : geometry.missing)
        notes.push_back("buffer '" + uri + "' is missing; it holds only geometry, which the lighting's needs do not read");
    return model;
}

} // namespace

bool isUnderstoodExtension(const std::string& name) {
    return kNeutralExtensions.contains(name) || kNeedsExtensions.contains(name);
}

SceneMaterials readSceneMaterials(const std::filesystem::path& file, bool strict) {
    SceneMaterials scene{file, {}, {}, {}};
    const auto model = load(file, scene.notes);
    for (size_t i = 0; i < model.materials.size(); ++i)
        scene.materials.push_back(needsOf(model, model.materials[i], i, {file, strict}));
    if (usesTheDefaultMaterial(model) || model.materials.empty()) {
        MaterialNeeds fallback;
        fallback.name = "the default material";
        fallback.roughness = ValueRange::of(1, 1);
        fallback.metalness = ValueRange::of(1, 1);
        scene.materials.push_back(fallback);
    }
    for (const auto& name : model.extensionsUsed)
        if (!isUnderstoodExtension(name)) scene.unknownExtensions.push_back(name);
    return scene;
}

} // namespace iblkit::scene
