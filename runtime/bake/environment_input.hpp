#pragma once

#include "float_image.hpp"
#include "texel_checks.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::bake {

enum class InputKind { BuiltIn, Panorama, Faces, Cube };
std::string_view inputKindName(InputKind kind);

struct InputFile {
    std::filesystem::path path;
    std::string sha256;
    std::vector<std::byte> bytes; // read once: hashed, then decoded from the same copy and released
};

// The built-in environment (hlsl/SkyCubeCS.hlsl) is rendered on the device straight into the
// cube, each texel the mean of kSkySupersample² evaluations over its footprint: the sun's disc,
// about 11 texels across at 256², keeps the cube's energy within 1.5e-5 of 16² evaluations
// (1.9e-3 at 64², where the disc is under 3 texels; tests/reference/sky_environment_test.cpp).
inline constexpr uint32_t kSkySupersample = 4;

struct InputPolicy {
    bool sanitize = false; // set NaN/Inf texels to 0 instead of refusing them
    bool strict = false;   // refuse negative texels instead of clamping them to 0
    const char* command = "bake"; // the command that reads it, as the messages name it
};

// An environment as read from disk, before any GPU work: either an equirectangular panorama
// or mip 0 of a cube (RGBA floats ordered face +X..-Z, row, column); nothing for the built-in one.
struct EnvironmentInput {
    InputKind kind = InputKind::BuiltIn;
    std::vector<InputFile> files;
    image_io::FloatImage panorama; // Panorama (the built-in environment is rendered on the device)
    uint32_t cubeSize = 0;         // Faces, Cube
    std::vector<float> cubeTexels;
    size_t sanitizedTexels = 0;    // NaN/Inf texels set to 0 (only with sanitize)
    NegativeTexels negative;       // texels with a negative colour channel, clamped to 0 (never with strict)
    InputPolicy policy;
    // False while only the files are read and hashed (readEnvironment): the panorama's size,
    // cubeSize and the counts above then come from InputFacts, and the texels are not there.
    bool decoded = true;
};

// What decoding an input found, everything a bake says of it but its texels: a cached bake
// describes its input from these without decoding it (bake_cache.hpp keeps them by the files'
// hashes and the policy).
struct InputFacts {
    uint32_t panoramaWidth = 0, panoramaHeight = 0, cubeSize = 0;
    size_t sanitizedTexels = 0;
    NegativeTexels negative;
};
InputFacts factsOf(const EnvironmentInput& input);
// The facts of `input`'s files, decoded earlier under the same policy, in place of decoding them.
void takeFacts(EnvironmentInput& input, const InputFacts& facts);


// ENV: an .hdr or .exr panorama (2:1), a folder of six faces (px, nx, py, ny, pz, nz or posx ...
// negz, each .hdr or .exr), or a .ktx2 / .dds cube; empty: the built-in environment. NaN/Inf
// texels are refused unless policy.sanitize, texels beyond ±kLargestRadiance always, and negative
// ones (lossy HDR compression leaves small ones) are clamped to 0 unless policy.strict. Throws
// BakeError or image_io::ImageError, one line each.
// Whether ENV names a cube (a .ktx2 or .dds file, or a folder of faces), whose own face size is
// the bake's, rather than a panorama.
bool isCubeInput(const std::filesystem::path& path);

EnvironmentInput loadEnvironment(const std::optional<std::filesystem::path>& path, const InputPolicy& policy);
// loadEnvironment in two halves: the files read and hashed (what names the input, and every
// refusal of a missing or misnamed file), then decoded and checked (a no-op once decoded).
EnvironmentInput readEnvironment(const std::optional<std::filesystem::path>& path, const InputPolicy& policy);
void decodeEnvironment(EnvironmentInput& input);

} // namespace iblkit::bake
