#include "environment_input.hpp"

#include "bake_error.hpp"
#include "file_names.hpp"
#include "files.hpp"
#include "image_error.hpp"
#include "sha256.hpp"
#include "texel_checks.hpp"
#include "texture.hpp"

#include <fmt/core.h>

#include <array>

namespace iblkit::bake {
namespace {

namespace fs = std::filesystem;

using image_io::quoted;

// Refuses NaN/Inf texels, or with `sanitize` sets them to 0; returns how many were set.
size_t checkFinite(std::span<float> values, uint32_t channels, uint32_t width, const std::string& name, bool sanitize,
                   const char* command) {
    const auto found = findNonFiniteTexels(values, channels);
    if (found.count == 0) return 0;
    if (!sanitize)
        throw BakeError(fmt::format("{} has {} NaN/Inf texel{} (the first at column {}, row {}: {}); "
                                    "{} with --sanitize to replace them by 0",
                                    name, found.count, found.count == 1 ? "" : "s", found.firstTexel % width,
                                    found.firstTexel / width, found.firstValue, command));
    return replaceNonFiniteTexels(values, channels);
}

void refuseOversized(std::span<const float> values, uint32_t channels, uint32_t width, const std::string& name,
                     const char* command) {
    if (const auto found = findOversizedTexel(values, channels))
        throw BakeError(fmt::format("{} has a texel of {:g} at column {}, row {}: the {} sums radiance in 32-bit "
                                    "floats, which overflow past {:g}",
                                    name, found->value, found->texel % width, found->texel / width, command,
                                    kLargestRadiance));
}

// Refuses negative texels with `strict`, or clamps them to 0; returns what it found.
NegativeTexels clampNegative(std::span<float> values, uint32_t channels, const std::string& name, bool strict,
                             const char* command) {
    const auto found = findNegativeTexels(values, channels);
    if (found.count == 0) return found;
    if (strict)
        throw BakeError(fmt::format("{} has {} texel{} of negative radiance (down to {:g}); {} without --strict to "
                                    "clamp them to 0",
                                    name, found.count, found.count == 1 ? "" : "s", found.mostNegative, command));
    clampNegativeToZero(values, channels);
    return found;
}

// Every check a loaded image's texels get, in order: NaN/Inf, then beyond the float sums' range,
// then negative.
void checkTexels(EnvironmentInput& input, std::span<float> values, uint32_t channels, uint32_t width,
                 const std::string& name, const InputPolicy& policy) {
    input.sanitizedTexels += checkFinite(values, channels, width, name, policy.sanitize, policy.command);
    refuseOversized(values, channels, width, name, policy.command);
    const auto negative = clampNegative(values, channels, name, policy.strict, policy.command);
    input.negative.count += negative.count;
    input.negative.mostNegative = std::min(input.negative.mostNegative, negative.mostNegative);
}

// The input's bytes are read once: hashed for the manifest and decoded from the same copy.
EnvironmentInput loadPanorama(const fs::path& path, const InputPolicy& policy) {
    const auto bytes = image_io::readFileBytes(path);
    EnvironmentInput input{InputKind::Panorama, {{path, cache::sha256Hex(bytes)}}, image_io::decodeFloatImage(bytes, path), 0, {}, 0, {}};
    auto& image = input.panorama;
    if (image.width != 2 * image.height)
        throw BakeError(fmt::format("{} is {}x{}; an equirectangular panorama must be twice as wide as it is high",
                                    quoted(path), image.width, image.height));
    checkTexels(input, image.values, image.channels, image.width, quoted(path), policy);
    return input;
}

fs::path findFace(const fs::path& folder, int face) {
    static const std::array<std::array<const char*, 2>, 6> kNames = {
        {{"px", "posx"}, {"nx", "negx"}, {"py", "posy"}, {"ny", "negy"}, {"pz", "posz"}, {"nz", "negz"}}};
    std::vector<fs::path> found;
    for (const char* name : kNames[face])
        for (const char* extension : {".hdr", ".exr"})
            if (fs::exists(folder / (std::string(name) + extension))) found.push_back(folder / (std::string(name) + extension));
    if (found.size() > 1)
        throw BakeError(fmt::format("{} has {} files for the {} face ({} and {}): keep one", quoted(folder), found.size(),
                                    std::array{"+X", "-X", "+Y", "-Y", "+Z", "-Z"}[face], quoted(found[0].filename()),
                                    quoted(found[1].filename())));
    if (found.size() == 1) return found.front();
    throw BakeError(fmt::format("{} has no {} face ({}.hdr, {}.exr, {}.hdr or {}.exr)", quoted(folder),
                                std::array{"+X", "-X", "+Y", "-Y", "+Z", "-Z"}[face], kNames[face][0], kNames[face][0],
                                kNames[face][1], kNames[face][1]));
}

EnvironmentInput loadFaces(const fs::path& folder, const InputPolicy& policy) {
    EnvironmentInput input{InputKind::Faces, {}, {}, 0, {}, 0, {}};
    for (int face = 0; face < 6; ++face) {
        const auto path = findFace(folder, face);
        const auto bytes = image_io::readFileBytes(path);
        auto image = image_io::decodeFloatImage(bytes, path);
        if (image.width != image.height)
            throw BakeError(fmt::format("{} is {}x{}; a cube face must be square", quoted(path), image.width, image.height));
        if (face == 0) input.cubeSize = image.width;
        if (image.width != input.cubeSize)
            throw BakeError(fmt::format("{} is {}x{}; the +X face is {}x{}", quoted(path), image.width, image.height,
                                        input.cubeSize, input.cubeSize));
        checkTexels(input, image.values, image.channels, image.width, quoted(path), policy);
        const auto rgba = image_io::rgbaValues(image);
        input.cubeTexels.insert(input.cubeTexels.end(), rgba.begin(), rgba.end());
        input.files.push_back({path, cache::sha256Hex(bytes)});
    }
    return input;
}

EnvironmentInput loadCubeFile(const fs::path& path, const InputPolicy& policy) {
    const auto bytes = image_io::readFileBytes(path);
    const auto texture = image_io::decodeTextureFile(bytes, path);
    if (texture.faces != 6) throw BakeError(quoted(path) + " is a 2D texture, not a cube");
    if (texture.width != texture.height) throw BakeError(quoted(path) + " has faces that are not square");
    if (image_io::channelCount(texture.format) != 4)
        throw BakeError(fmt::format("{} is {}; an environment cube needs RGBA texels", quoted(path),
                                    image_io::vulkanFormatName(texture.format)));
    auto values = image_io::textureValues(texture);
    values.resize(size_t(6) * texture.width * texture.height * 4); // mip 0; the bake makes its own chain
    EnvironmentInput input{InputKind::Cube, {{path, cache::sha256Hex(bytes)}}, {}, texture.width, std::move(values), 0, {}};
    // Face by face, so that a texel is named by its face's own column and row.
    const size_t faceValues = size_t(texture.width) * texture.height * 4;
    for (size_t face = 0; face < 6; ++face)
        checkTexels(input, std::span(input.cubeTexels).subspan(face * faceValues, faceValues), 4, texture.width,
                    quoted(path) + " face " + std::array{"+X", "-X", "+Y", "-Y", "+Z", "-Z"}[face], policy);
    return input;
}

} // namespace

std::string_view inputKindName(InputKind kind) {
    switch (kind) {
    case InputKind::BuiltIn: return "built-in";
    case InputKind::Panorama: return "equirectangular";
    case InputKind::Faces: return "faces";
    case InputKind::Cube: return "cube";
    }
    return "?";
}

EnvironmentInput loadEnvironment(const std::optional<fs::path>& path, const InputPolicy& policy) {
    if (!path) return {InputKind::BuiltIn, {}, {}, 0, {}, 0, {}};
    std::error_code error;
    if (!fs::exists(*path, error)) throw BakeError("cannot open " + quoted(*path) + ": No such file or directory");
    if (!isCubeInput(*path)) return loadPanorama(*path, policy);
    return fs::is_directory(*path, error) ? loadFaces(*path, policy) : loadCubeFile(*path, policy);
}

bool isCubeInput(const std::filesystem::path& path) {
    std::error_code error;
    const std::string extension = image_io::lowerExtension(path);
    return std::filesystem::is_directory(path, error) || extension == ".ktx2" || extension == ".dds";
}

} // namespace iblkit::bake
