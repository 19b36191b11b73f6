#pragma once

#include <filesystem>
#include <string_view>

namespace iblkit::scene {

// What tinygltf reads without a word and the kit must not: a glTF whose asset.version is not 2.x,
// `materials` that is not an array of objects, a factor the needs read that is not a number (or a
// baseColorFactor not of four), and an index (a primitive's material, a texture's source, a
// material's texture) outside its array. SceneError "<file>: error: <where>: <what>".
void requireGltfShape(std::string_view json, const std::filesystem::path& file);

} // namespace iblkit::scene
