#pragma once

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace tinygltf {
class TinyGLTF;
}

namespace iblkit::scene {

// One policy for a scene file and every file it names (buffers, images): a regular file (not a
// folder, a device or a pipe, which is opened without waiting for a writer), of at most
// kMaxSceneFileBytes, its JSON nested at most kMaxJsonNesting deep. tinygltf's parser recurses
// once a level: 20,000 nested arrays overflowed the stack.
inline constexpr uint64_t kMaxSceneFileBytes = uint64_t(1) << 30;
inline constexpr size_t kMaxJsonNesting = 256;

// The whole file (image_io::readFileBytes, bounded), or SceneError "<path>: error: <why>".
std::vector<std::byte> readSceneFile(const std::filesystem::path& path);

// SceneError naming `path` when `json`'s arrays and objects nest deeper than kMaxJsonNesting.
void requireJsonNestingWithin(std::string_view json, const std::filesystem::path& path);

// A file a scene names, refused by the policy: "cannot open '<that file>': <why>", for the
// reader to put after the scene's own name.
struct ReferencedFileRefused : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The external buffers of a scene (`uris`), and those that hold only geometry (no image's
// bufferView lies in them) with their byteLength. What the kit reads of a scene is its materials
// and their textures, so a geometry buffer that is missing is read as zeros, and named in
// `missing`; any other missing buffer is refused in the kit's words.
struct GeometryBuffers {
    std::set<std::string> uris;
    std::map<std::string, uint64_t> byteLengths;
    std::vector<std::string> missing;
};
GeometryBuffers geometryOnlyBuffers(const nlohmann::json& gltf);

// tinygltf reads the files a scene names by the same policy; a refusal is ReferencedFileRefused,
// thrown through tinygltf. A missing buffer of `geometry` is zeros instead.
void readReferencedFilesByThePolicy(tinygltf::TinyGLTF& loader, GeometryBuffers& geometry);

} // namespace iblkit::scene
