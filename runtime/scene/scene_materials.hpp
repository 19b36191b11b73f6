#pragma once

#include "value_range.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::scene {

// What image-based lighting one glTF material needs, after its factors and its textures' texels.
struct MaterialNeeds {
    std::string name;  // the material's name, or "material N"
    bool unlit = false; // KHR_materials_unlit: it needs no lighting at all
    ValueRange roughness;  // perceptual roughness (glTF's), over the metallicRoughnessTexture's texels
    ValueRange metalness;
    ValueRange clearcoatRoughness;      // KHR_materials_clearcoat with a clearcoat: a second specular lobe
    bool transmission = false;          // KHR_materials_transmission or _volume: refraction reads the specular chain
    std::vector<std::string> notes;     // what was assumed or clamped (a texture whose texels could not be read, a factor past 1)
    std::vector<std::string> unknownExtensions; // extensions on the material the kit does not understand
};

struct SceneMaterials {
    std::filesystem::path file;
    std::vector<MaterialNeeds> materials;
    std::vector<std::string> unknownExtensions; // the scene's extensionsUsed the kit does not understand
    std::vector<std::string> notes;             // about the scene as a whole (a missing geometry buffer)
};

// Reads a glTF 2.0 scene (.gltf with its buffers and images, or .glb) with tinygltf and derives
// each material's needs. A scene without materials has glTF's default material (roughness 1,
// metalness 1). A roughness, metallic or clearcoat roughness factor outside [0, 1] is clamped
// into it with a note, or with `strict` refused. Throws SceneError naming the file and the problem.
SceneMaterials readSceneMaterials(const std::filesystem::path& file, bool strict = false);

// The extensions that the needs above account for.
bool isUnderstoodExtension(const std::string& name);

} // namespace iblkit::scene
