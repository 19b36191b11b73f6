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

void decodePanorama(EnvironmentInput& input) {
    auto& file = input.files.front();
    input.panorama = image_io::decodeFloatImage(file.bytes, file.path);
    auto& image = input.panorama;
    if (image.width != 2 * image.height)
        throw BakeError(fmt::format("{} is {}x{}; an equirectangular panorama must be twice as wide as it is high",
                                    quoted(file.path), image.width, image.height));
    checkTexels(input, image.values, image.channels, image.width, quoted(file.path), input.policy);
}

InputFile readInputFile(const fs::path& path) {
    auto bytes = image_io::readFileBytes(path);
    auto digest = cache::sha256Hex(bytes);
    return {path, std::move(digest), std::move(bytes)};
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

void decodeFaces(EnvironmentInput& input) {
    for (int face = 0; face < 6; ++face) {
        const auto& file = input.files[face];
        auto image = image_io::decodeFloatImage(file.bytes, file.path);
        if (image.width != image.height)
            throw BakeError(fmt::format("{} is {}x{}; a cube face must be square", quoted(file.path), image.width, image.height));
        if (face == 0) input.cubeSize = image.width;
        if (image.width != input.cubeSize)
            throw BakeError(fmt::format("{} is {}x{}; the +X face is {}x{}", quoted(file.path), image.width, image.height,
                                        input.cubeSize, input.cubeSize));
        checkTexels(input, image.values, image.channels, image.width, quoted(file.path), input.policy);
        const auto rgba = image_io::rgbaValues(image);
        input.cubeTexels.insert(input.cubeTexels.end(), rgba.begin(), rgba.end());
    }
}

void decodeCubeFile(EnvironmentInput& input) {
    const auto& path = input.files.front().path;
    const auto texture = image_io::decodeTextureFile(input.files.front().bytes, path);
    if (texture.faces != 6) throw BakeError(quoted(path) + " is a 2D texture, not a cube");
    if (texture.width != texture.height) throw BakeError(quoted(path) + " has faces that are not square");
    if (image_io::channelCount(texture.format) != 4)
        throw BakeError(fmt::format("{} is {}; an environment cube needs RGBA texels", quoted(path),
                                    image_io::vulkanFormatName(texture.format)));
    input.cubeTexels = image_io::textureValues(texture);
    input.cubeTexels.resize(size_t(6) * texture.width * texture.height * 4); // mip 0; the bake makes its own chain
    input.cubeSize = texture.width;
    // Face by face, so that a texel is named by its face's own column and row.
    const size_t faceValues = size_t(texture.width) * texture.height * 4;
    for (size_t face = 0; face < 6; ++face)
        checkTexels(input, std::span(input.cubeTexels).subspan(face * faceValues, faceValues), 4, texture.width,
                    quoted(path) + " face " + std::array{"+X", "-X", "+Y", "-Y", "+Z", "-Z"}[face], input.policy);
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

EnvironmentInput readEnvironment(const std::optional<fs::path>& path, const InputPolicy& policy) {
    EnvironmentInput input;
    input.policy = policy;
    if (!path) return input;
    std::error_code error;
    if (!fs::exists(*path, error)) throw BakeError("cannot open " + quoted(*path) + ": No such file or directory");
    input.decoded = false;
    if (!isCubeInput(*path)) {
        input.kind = InputKind::Panorama;
        input.files.push_back(readInputFile(*path));
    } else if (fs::is_directory(*path, error)) {
        input.kind = InputKind::Faces;
        for (int face = 0; face < 6; ++face) input.files.push_back(readInputFile(findFace(*path, face)));
    } else {
        input.kind = InputKind::Cube;
        input.files.push_back(readInputFile(*path));
    }
    return input;
}

void decodeEnvironment(EnvironmentInput& input) {
    if (input.decoded) return;
    input.sanitizedTexels = 0;
    input.negative = {};
    if (input.kind == InputKind::Panorama) decodePanorama(input);
    else if (input.kind == InputKind::Faces) decodeFaces(input);
    else decodeCubeFile(input);
    for (auto& file : input.files) file.bytes = {};
    input.decoded = true;
}

EnvironmentInput loadEnvironment(const std::optional<fs::path>& path, const InputPolicy& policy) {
    auto input = readEnvironment(path, policy);
    decodeEnvironment(input);
    return input;
}

InputFacts factsOf(const EnvironmentInput& input) {
    return {input.panorama.width, input.panorama.height, input.cubeSize, input.sanitizedTexels, input.negative};
}

void takeFacts(EnvironmentInput& input, const InputFacts& facts) {
    input.panorama.width = facts.panoramaWidth;
    input.panorama.height = facts.panoramaHeight;
    input.cubeSize = facts.cubeSize;
    input.sanitizedTexels = facts.sanitizedTexels;
    input.negative = facts.negative;
}

bool isCubeInput(const std::filesystem::path& path) {
    std::error_code error;
    const std::string extension = image_io::lowerExtension(path);
    return std::filesystem::is_directory(path, error) || extension == ".ktx2" || extension == ".dds";
}

} // namespace iblkit::bake
