#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::bench {

// The scenes the bake bench plans for, each one kind of what engines ship: their materials only.
struct BenchScene {
    std::string name;
    std::string gltf; // a glTF 2.0 file's text
};
const std::vector<BenchScene>& benchScenes();

// Writes `scene` as NAME.gltf into `folder`; returns its path.
std::filesystem::path writeBenchScene(const BenchScene& scene, const std::filesystem::path& folder);

} // namespace iblkit::bench
