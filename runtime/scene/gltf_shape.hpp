#pragma once

#include <nlohmann/json_fwd.hpp>

#include <filesystem>

namespace iblkit::scene {

// What tinygltf reads without a word and the kit must not: a glTF whose asset.version is not 2.x,
// `materials` that is not an array of objects, a factor the needs read that is not a number (or a
// baseColorFactor not of four), and an index (a primitive's material, a texture's source, a
// material's texture) outside its array. SceneError "<file>: error: <where>: <what>". A scene
// that is not JSON at all (`gltf` discarded) passes: tinygltf's own message says where.
void requireGltfShape(const nlohmann::json& gltf, const std::filesystem::path& file);

} // namespace iblkit::scene
