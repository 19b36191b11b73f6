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
};

// The built-in environment (hlsl/SkyCubeCS.hlsl) is rendered on the device straight into the
// cube, each texel the mean of kSkySupersample² evaluations over its footprint: the sun's disc,
// about 11 texels across at 256², keeps the cube's energy within 1.5e-5 of 16² evaluations
// (1.9e-3 at 64², where the disc is under 3 texels; tests/reference/sky_environment_test.cpp).
inline constexpr uint32_t kSkySupersample = 4;

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
};

struct InputPolicy {
    bool sanitize = false; // set NaN/Inf texels to 0 instead of refusing them
    bool strict = false;   // refuse negative texels instead of clamping them to 0
    const char* command = "bake"; // the command that reads it, as the messages name it
};

// ENV: an .hdr or .exr panorama (2:1), a folder of six faces (px, nx, py, ny, pz, nz or posx ...
// negz, each .hdr or .exr), or a .ktx2 / .dds cube; empty: the built-in environment. NaN/Inf
// texels are refused unless policy.sanitize, texels beyond ±kLargestRadiance always, and negative
// ones (lossy HDR compression leaves small ones) are clamped to 0 unless policy.strict. Throws
// BakeError or image_io::ImageError, one line each.
// Whether ENV names a cube (a .ktx2 or .dds file, or a folder of faces), whose own face size is
// the bake's, rather than a panorama.
bool isCubeInput(const std::filesystem::path& path);

EnvironmentInput loadEnvironment(const std::optional<std::filesystem::path>& path, const InputPolicy& policy);

} // namespace iblkit::bake
