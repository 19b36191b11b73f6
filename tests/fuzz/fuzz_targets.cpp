#include "fuzz_targets.hpp"

#include "bake_cache.hpp"
#include "cache_error.hpp"
#include "compile_error.hpp"
#include "content_store.hpp"
#include "compiler.hpp"
#include "dds.hpp"
#include "float_image.hpp"
#include "image_error.hpp"
#include "ktx2.hpp"
#include "lowering.hpp"
#include "lowering_error.hpp"
#include "render/lights_file.hpp"
#include "render/render_error.hpp"
#include "run_error.hpp"
#include "run_file.hpp"
#include "scratch_folder.hpp"
#include "scene_error.hpp"
#include "scene_materials.hpp"
#include "shader_manifest.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace iblkit::fuzz {
namespace {

std::string text(std::span<const std::byte> bytes) { return {reinterpret_cast<const char*>(bytes.data()), bytes.size()}; }

// A decoder of bytes in memory, fed any bytes: an ImageError is its one allowed end.
template <typename Decode>
void decodeImage(std::span<const std::byte> bytes, Decode decode) {
    try {
        decode(bytes);
    } catch (const image_io::ImageError&) {}
}

void radianceHdr(std::span<const std::byte> bytes) {
    decodeImage(bytes, [](auto in) { image_io::decodeRadianceHdr(in, "fuzz.hdr"); });
}
void exr(std::span<const std::byte> bytes) {
    decodeImage(bytes, [](auto in) { image_io::decodeExr(in, "fuzz.exr"); });
}
void ktx2(std::span<const std::byte> bytes) {
    decodeImage(bytes, [](auto in) { image_io::decodeKtx2(in, "fuzz.ktx2"); });
}
void dds(std::span<const std::byte> bytes) {
    decodeImage(bytes, [](auto in) { image_io::decodeDds(in, "fuzz.dds"); });
}

void runFile(std::span<const std::byte> bytes) {
    try {
        run::parseRunFile(text(bytes), "fuzz.run.json");
    } catch (const run::RunError&) {}
}

void shaderManifest(std::span<const std::byte> bytes) {
    try {
        compiler::parseShaderManifest(text(bytes), "fuzz/shaders.json");
    } catch (const compiler::CompileError&) {}
}

// The whole compile entry as the command-line tool runs it (glslang first in a bounded child,
// since glslang itself crashes on some sources): preprocessing, glslang, SPIRV-Tools,
// reflection; no file is read.
void hlsl(std::span<const std::byte> bytes) {
    compiler::CompileOptions options;
    options.source = "fuzz.hlsl";
    options.sourceText = text(bytes);
    options.boundPreprocessing = true;
    try {
        compiler::compileShader(options);
    } catch (const compiler::CompileError&) {}
}

// The HLSL 2021 lowering alone, in process (the hlsl target runs it too, but forks per input).
void hlslLowering(std::span<const std::byte> bytes) {
    try {
        lowering::lowerHlsl(text(bytes), "fuzz.hlsl", lowering::HlslVersion::Hlsl2021);
    } catch (const lowering::LoweringError&) {}
}

// A scratch folder of this process, for the targets that read files; removed at exit.
const std::filesystem::path& scratchFolder() {
    static const files::ScratchFolder folder("fuzz");
    return folder.path();
}

std::filesystem::path written(const std::filesystem::path& path, std::span<const std::byte> bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return path;
}

// A glTF scene as `plan` and `bake --scene` read it: tinygltf, the kit's shape checks and the
// scene file policy for what it references (which resolves beside the file, in the scratch
// folder). Both the JSON and the binary container, strict or not.
void readScene(std::span<const std::byte> bytes, const char* name) {
    const auto file = written(scratchFolder() / name, bytes);
    for (const bool strict : {false, true}) {
        try {
            scene::readSceneMaterials(file, strict);
        } catch (const scene::SceneError&) {}
    }
}
void gltf(std::span<const std::byte> bytes) { readScene(bytes, "fuzz.gltf"); }
void glb(std::span<const std::byte> bytes) { readScene(bytes, "fuzz.glb"); }

void lightsFile(std::span<const std::byte> bytes) {
    try {
        render::parseLights(text(bytes), "fuzz.lights.json");
    } catch (const render::RenderError&) {}
}

// A cache entry as a bake reads it: the store's framing (magic, key, checksum) on a file in the
// cache's layout, then, since no fuzzer forges a SHA-256, the payload decoders on the bytes as
// they are. Each decoder returns a value or nothing.
void cacheEntry(std::span<const std::byte> bytes) {
    const auto payload = text(bytes);
    // The key the entry names, when it names one, so that the checks past the key are reached.
    std::string key = payload.substr(0, std::min<size_t>(payload.size(), 72));
    key = key.size() == 72 && key.find_first_not_of("0123456789abcdef", 8) == std::string::npos ? key.substr(8)
                                                                                                   : std::string(64, 'a');
    cache::ContentStore store(scratchFolder() / "cache");
    std::filesystem::create_directories(scratchFolder() / "cache" / "objects" / key.substr(0, 2));
    written(scratchFolder() / "cache" / "objects" / key.substr(0, 2) / key, bytes);
    try {
        store.get(key);
    } catch (const cache::CacheError&) {}
    bake::textureFromPayload(payload);
    bake::irradianceFromPayload(payload);
    bake::lightsFromPayload(payload);
}

} // namespace

const std::vector<Target>& targets() {
    static const std::vector<Target> all{{"radiance_hdr", radianceHdr}, {"exr", exr},
                                         {"ktx2", ktx2},                 {"dds", dds},
                                         {"run_file", runFile},          {"shader_manifest", shaderManifest},
                                         {"hlsl", hlsl},                 {"hlsl_lowering", hlslLowering},
                                         {"gltf", gltf},                 {"glb", glb},
                                         {"lights_file", lightsFile},    {"cache_entry", cacheEntry}};
    return all;
}

} // namespace iblkit::fuzz
