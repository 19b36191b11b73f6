#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace iblkit {

enum class LutFormat { Rg16Float, Rg32Float };

// What a bake computes and how (docs/bake.md has each setting's meaning and measured defaults).
// Names of methods, recipes and profiles are as the command line takes them.
struct BakeRequest {
    // An equirectangular .hdr or .exr, a folder of six faces, or a .ktx2 / .dds cube; empty: the
    // built-in sky.
    std::optional<std::filesystem::path> environment;
    std::optional<std::filesystem::path> scene; // a glTF scene: bake only what its materials need
    std::optional<uint32_t> size;               // cube face size, a power of two; default 256, or the input cube's
    std::optional<uint32_t> mips;               // specular mips; default: down to the profile's last mip size
    std::string method = "convolution";         // the prefilter: convolution, table, filtered, pyramid, mipchain, document
    std::optional<uint32_t> samples;            // the method's samples (the convolution's budget of terms); default by method
    std::optional<std::string> recipe;          // the shading recipe the maps are made for; default by profile and method
    std::string profile = "iblkit";             // the engine whose conventions the maps follow
    uint32_t lutSize = 512;
    std::string lutMethod = "quadrature-grid";  // or quadrature, fit, document
    std::optional<uint32_t> lutSamples;         // default by LUT method
    LutFormat lutFormat = LutFormat::Rg16Float; // of brdf_lut.ktx2; the LUT in memory is 32-bit either way
    uint32_t irradianceSize = 32;
    bool dds = false;      // a folder bake also writes .dds files
    bool exr = false;      // a folder bake also writes every face and mip as EXR under exr/
    bool sanitize = false; // NaN/Inf input texels become 0 instead of refusing the input
    bool strict = false;   // refuse negative input texels and values past 65504 in 16-bit files instead of clamping them
    // A content store: each output is kept under the hash of everything it depends on and taken
    // from there when nothing changed. Empty: no cache. The command line's default is defaultCacheFolder().
    std::optional<std::filesystem::path> cache;
    std::string device;      // a device index or part of its name; empty: $IBLKIT_DEVICE, else lavapipe
    bool validation = false; // the Vulkan validation layer on (and the cache neither read nor written)
    bool quiet = true;       // no progress lines on stderr
};

// The command line's cache: $XDG_CACHE_HOME/iblkit, else ~/.cache/iblkit.
std::filesystem::path defaultCacheFolder();

// One mip of a cube: six square faces in the order +X, -X, +Y, -Y, +Z, -Z of the profile's frame,
// each size x size texels of RGBA floats, row by row from the top, as the KTX2 file holds them.
struct CubeMip {
    uint32_t size = 0;
    std::array<std::vector<float>, 6> faces;
};

// A 2D image of `channels` floats a texel, row by row from the top.
struct Image2D {
    uint32_t width = 0, height = 0, channels = 0;
    std::vector<float> values;
};

// A bright source the recipe took out of the environment, to be shaded as a light.
struct EnvironmentLight {
    std::array<double, 3> direction{0, 0, 1}; // unit, towards the light
    std::array<double, 3> radiance{};         // of its disk
    double solidAngle = 0;
    double angularRadius = 0; // of a disk of that solid angle, in radians
    double share = 0;         // of the environment's light
};

// The maps of a bake, with the values the device computed: before the files' 16-bit rounding
// and the half-range policy. An output a scene does not need is empty.
struct BakedMaps {
    std::vector<CubeMip> specular;       // the prefiltered chain
    std::vector<float> specularRoughness; // the roughness each specular mip holds (mip 0: 0, the source)
    // The split sum's (scale, bias): column x at N·V = (x + 0.5) / width, row y at roughness (y + 0.5) / height.
    Image2D brdfLut;
    CubeMip irradiance; // E(n) / pi: multiply by the albedo for Lambertian diffuse
    Image2D lobeTable;  // where the recipe reads its lobe through one (the kit's recipe), else empty
    std::vector<EnvironmentLight> lights;
    // The radiance's projection on the nine real SH of bands 0 to 2 (order (0,0), (1,-1), (1,0),
    // (1,1), (2,-2) ... (2,2)), of the environment without its lights, RGB each.
    std::array<std::array<double, 3>, 9> shRadiance{};
    std::string shading; // the shading record as JSON: how the maps are read (docs/bake.md)
    std::string device;
    std::vector<std::string> validationMessages; // with validation on: any message means the bake is suspect
};

// Bakes in memory; writes nothing (but the cache, when one is given). Throws Error: BadInput for
// a request or an input refused before any work, BakeFailed, DeviceFailed, CompileFailed.
BakedMaps bakeToMemory(const BakeRequest& request);

struct BakeStep {
    std::string name;
    double deviceMilliseconds = 0; // summed over the step's dispatches; 0 for a host step
    double wallMilliseconds = 0;
};

struct WrittenFile {
    std::string name; // relative to the folder
    std::string sha256;
    size_t bytes = 0;
};

// A 16-bit texture's values past 65504, clamped (without `strict`), and what that cost.
struct HalfRangeClamp {
    std::string texture;
    size_t values = 0;
    uint32_t worstMip = 0;  // the mip that lost the largest share of its energy
    double worstShare = 0;  // that share
};

struct CacheCounts {
    size_t hits = 0, misses = 0, damaged = 0;
};

struct KernelCacheCounts {
    size_t hits = 0, misses = 0, stale = 0, damaged = 0;
};

struct BakeSummary {
    std::filesystem::path folder;
    std::string device;
    std::vector<BakeStep> steps;
    double wallMilliseconds = 0;
    std::vector<WrittenFile> files;
    std::array<std::array<double, 3>, 9> shRadiance{}; // as BakedMaps::shRadiance
    std::vector<HalfRangeClamp> halfRangeClamps;
    size_t sanitizedTexels = 0; // NaN/Inf input texels set to 0 (`sanitize`)
    size_t negativeTexels = 0;  // input texels of negative radiance, clamped to 0
    float mostNegative = 0;     // their most negative channel
    CacheCounts cache;
    std::vector<std::string> cacheWarnings; // why an output could not be cached (the bake went on)
    KernelCacheCounts compiledKernels;      // kernels taken from the cache, and compiled
    size_t pipelineCacheBytes = 0;          // Vulkan pipeline cache data an earlier bake on this device left
    std::vector<std::string> sceneNotes;    // what the scene's reader assumed or clamped (a material factor outside [0, 1])
    std::vector<std::string> validationMessages; // with validation on: any message means the bake is suspect
    std::string json; // the summary (without the validation messages) as `iblkit bake --json` prints it
};

// Bakes into `folder` as `iblkit bake -o FOLDER` does: specular.ktx2, brdf_lut.ktx2,
// irradiance.ktx2, preview.png, manifest.json and what the recipe and flags add, all or nothing.
// The folder must be absent, empty, or an earlier bake. Throws Error as bakeToMemory.
BakeSummary bakeToFolder(const BakeRequest& request, const std::filesystem::path& folder);

} // namespace iblkit
