#include "scene_files.hpp"

#include "files.hpp"
#include "image_error.hpp"
#include "scene_error.hpp"

#include <tiny_gltf.h>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <set>

namespace iblkit::scene {
namespace {

bool exists(const std::string& path) {
    std::error_code error;
    return std::filesystem::exists(path, error);
}

// Whether tinygltf's `path` (the scene's folder joined to a URI) is that URI's.
bool names(const std::string& path, const std::string& uri) { return path == uri || path.ends_with("/" + uri); }

// The geometry-only buffer at `path`, if any.
const std::pair<const std::string, uint64_t>* geometryBufferAt(const std::string& path, const GeometryBuffers& geometry) {
    for (const auto& buffer : geometry.byteLengths)
        if (names(path, buffer.first)) return &buffer;
    return nullptr;
}

// A buffer is said to exist, so that readWhole reads it (or refuses it in the kit's words, not
// tinygltf's "File not found"); an image that is missing is tinygltf's to note.
bool fileExists(const std::string& path, void* data) {
    const auto& geometry = *static_cast<GeometryBuffers*>(data);
    return exists(path) || std::any_of(geometry.uris.begin(), geometry.uris.end(), [&](const auto& uri) { return names(path, uri); });
}

std::string pathAsIs(const std::string& path, void*) { return path; }

bool readWhole(std::vector<unsigned char>* out, std::string*, const std::string& path, void* data) {
    auto& geometry = *static_cast<GeometryBuffers*>(data);
    if (const auto* buffer = geometryBufferAt(path, geometry); buffer && !exists(path)) {
        out->assign(buffer->second, 0);
        geometry.missing.push_back(buffer->first);
        return true;
    }
    try {
        const auto bytes = image_io::readFileBytes(path, kMaxSceneFileBytes);
        const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
        out->assign(data, data + bytes.size());
    } catch (const image_io::ImageError& error) {
        throw ReferencedFileRefused(error.what());
    }
    return true;
}

bool writeNothing(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
    *error = "a scene is only read";
    return false;
}

} // namespace

std::vector<std::byte> readSceneFile(const std::filesystem::path& path) {
    try {
        return image_io::readFileBytes(path, kMaxSceneFileBytes);
    } catch (const image_io::ImageError& error) {
        throw SceneError(fmt::format("{}: error: {}", path.string(), error.what()));
    }
}

void requireJsonNestingWithin(std::string_view json, const std::filesystem::path& path) {
    size_t depth = 0;
    bool inString = false, escaped = false;
    for (const char c : json) {
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonNesting)
                throw SceneError(fmt::format("{}: error: its JSON nests arrays and objects more than {} deep", path.string(),
                                             kMaxJsonNesting));
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
}

GeometryBuffers geometryOnlyBuffers(const nlohmann::json& json) {
    GeometryBuffers geometry;
    if (!json.is_object() || !json.contains("buffers") || !json["buffers"].is_array()) return geometry;
    std::set<uint64_t> imageBuffers;
    const auto views = json.value("bufferViews", nlohmann::json::array());
    for (const auto& image : json.value("images", nlohmann::json::array()))
        if (image.is_object() && image.contains("bufferView") && image["bufferView"].is_number_unsigned()) {
            const auto view = image["bufferView"].get<uint64_t>();
            if (views.is_array() && view < views.size() && views[view].is_object() && views[view].contains("buffer") &&
                views[view]["buffer"].is_number_unsigned())
                imageBuffers.insert(views[view]["buffer"].get<uint64_t>());
        }
    const auto& buffers = json["buffers"];
    for (size_t i = 0; i < buffers.size(); ++i) {
        const auto& buffer = buffers[i];
        if (!buffer.is_object() || !buffer.contains("uri") || !buffer["uri"].is_string()) continue;
        const auto uri = buffer["uri"].get<std::string>();
        if (!uri.starts_with("data:")) geometry.uris.insert(uri);
        if (imageBuffers.contains(i) || !buffer.contains("byteLength") || !buffer["byteLength"].is_number_unsigned()) continue;
        // The bound keeps a stated length from becoming an allocation no file would have been.
        if (!uri.starts_with("data:") && buffer["byteLength"].get<uint64_t>() <= kMaxSceneFileBytes)
            geometry.byteLengths[uri] = buffer["byteLength"].get<uint64_t>();
    }
    return geometry;
}

void readReferencedFilesByThePolicy(tinygltf::TinyGLTF& loader, GeometryBuffers& geometry) {
    loader.SetFsCallbacks({fileExists, pathAsIs, readWhole, writeNothing, &geometry});
}

} // namespace iblkit::scene
