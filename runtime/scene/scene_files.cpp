#include "scene_files.hpp"

#include "files.hpp"
#include "image_error.hpp"
#include "scene_error.hpp"

#include <tiny_gltf.h>

#include <fmt/core.h>

namespace iblkit::scene {
namespace {

bool fileExists(const std::string& path, void*) {
    std::error_code error;
    return std::filesystem::exists(path, error);
}

std::string pathAsIs(const std::string& path, void*) { return path; }

bool readWhole(std::vector<unsigned char>* out, std::string*, const std::string& path, void*) {
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

void readReferencedFilesByThePolicy(tinygltf::TinyGLTF& loader) {
    loader.SetFsCallbacks({fileExists, pathAsIs, readWhole, writeNothing, nullptr});
}

} // namespace iblkit::scene
