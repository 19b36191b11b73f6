#pragma once

#include "kernels/lut_methods.hpp"
#include "profiles/engine_profile.hpp"
#include "shading/shading_recipe.hpp"
#include "kernels/sampled_methods.hpp"
#include "context_options.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::bake {

enum class LutFormat { Rg16Float, Rg32Float };

// The prefilter the bake runs unless told otherwise, chosen from the bench (docs/bench.md): at a
// budget of 128 terms per texel the convolution is within 0.7 % RMS and 2.9 % max of the converged
// integral on the built-in sky, a one-texel sun and Blender's eight HDRIs, where the documents'
// estimator at 1024 samples is off by tens of percent.
inline constexpr const char* kDefaultSpecularMethod = "convolution";
inline constexpr uint32_t kDefaultConvolutionBudget = 128;
inline constexpr uint32_t kDefaultPyramidReads = 1;
inline constexpr uint32_t kDocumentSamples = 1024; // the documents' SAMPLE_COUNT
// The LUT method the bake runs unless told otherwise: the quadrature grid meets both LUT targets
// at 512² (docs/bench.md) in a sixth of the full quadrature's time, where the documents'
// estimator at 1024 samples is 1e-2 off.
inline constexpr const char* kDefaultLutMethod = kernels::kQuadratureGridLutMethod;
// The polynomial's degree unless told otherwise: 6.5e-2 from the converged LUT (tests/reference).
inline constexpr uint32_t kDefaultLutFitDegree = 5;

struct BakeSettings {
    std::optional<std::filesystem::path> environment; // empty: the built-in environment
    std::optional<std::filesystem::path> scene;       // a glTF scene: bake only what its materials need (bake_plan.hpp)
    std::optional<std::filesystem::path> cache;       // a content store's folder (runtime/cache/); empty: no cache
    std::filesystem::path outputDir;
    std::optional<uint32_t> size;   // cube face size; default 256, or the input cube's own size
    std::optional<uint32_t> mips;   // specular mips; default: down to the profile's last mip size (8 for the kit's)
    std::string specularMethod = kDefaultSpecularMethod; // a prefilter method of the kernel table
    std::optional<uint32_t> samples; // samples (budget of terms, for the convolution); default by method
    // The shading recipe the maps are made for (runtime/shading/shading_recipe.hpp): the lights
    // taken out, the prefilter's lobe, each mip's roughness. Default: the kit's for the
    // convolution, the documents' for every other method (they prefilter the documents' N·L lobe).
    std::optional<std::string> recipe;
    // The engine whose conventions the files follow (runtime/profiles/engine_profile.hpp): its
    // recipe unless --recipe names another of the same lod mapping, its cube frame, its chain.
    std::string profile = "iblkit";
    uint32_t lutSize = 512;
    std::string lutMethod = kDefaultLutMethod; // a LUT method of the kernel table
    std::optional<uint32_t> lutSamples; // samples (nodes per panel, for the quadrature; per side, for its grid); default by method
    LutFormat lutFormat = LutFormat::Rg16Float;
    uint32_t irradianceSize = 32;
    bool dds = false;
    bool exr = false;
    bool sanitize = false;  // replace NaN/Inf input texels by 0 instead of refusing them
    bool strict = false;    // refuse negative input texels and values beyond half range in 16-bit outputs instead of clamping them
    vulkan::ContextOptions context; // device selector and validation, as for every command
};

// The preview's exposure range: 2^±30 about 1 covers environments from a night sky to an
// unclipped sun; past it the preview is black or white.
inline constexpr double kMinPreviewExposure = 1.0 / (1 << 30);
inline constexpr double kMaxPreviewExposure = double(1 << 30);

inline constexpr uint32_t kDefaultSize = 256;
// Sizes past these are refused before any work: a 16384² cube with its chain is ~8.6 GB as floats.
inline constexpr uint32_t kMaxCubeSize = 16384;
inline constexpr uint32_t kMaxLutSize = 16384;
inline constexpr uint32_t kMaxIrradianceSize = 1024;

// A bake's settings with every default and every name resolved once, at the edge: the plan and the
// steps read these, never the optionals they came from. The face size and chain are the setting's
// (or the default's) until a cube input is read, whose own size then decides them (resolveFaceSize).
struct ResolvedSettings : BakeSettings {
    const profiles::EngineProfile* engineProfile = nullptr; // the one `profile` names
    // `recipe`'s, else the profile's, else the method's default (the kit's for the convolution, the
    // documents' for every other method: they prefilter the documents' N·L lobe).
    const shading::ShadingRecipe* shadingRecipe = nullptr;
    uint32_t sampleCount = 0;    // `samples`, or the method's default
    uint32_t lutSampleCount = 0; // `lutSamples`, or the LUT method's default
    uint32_t faceSize = 0;       // `size`, or 256, or the input cube's own
    // `mips`, or the chain down to the profile's last mip size (8 for the kit's), the last at roughness 1.
    uint32_t mipCount = 0;
};

// Checks and resolves every setting. Throws BakeError naming the first one out of range (the
// output folder is prepareBake's).
ResolvedSettings resolveSettings(const BakeSettings& settings);
// The face size and chain for an input cube of `inputCubeSize` (0: a panorama or the built-in sky,
// which take the setting's or the default): a cube's own size, which --size must match if given.
// resolveSettings calls it with 0 unless a chain is asked without a size, which waits for the
// input's. Throws BakeError.
void resolveFaceSize(ResolvedSettings& settings, uint32_t inputCubeSize);
// The specular mip count of a chain from a `size` face down to `lastMipSize` (or to 1x1).
uint32_t chainDownTo(uint32_t size, uint32_t lastMipSize);
// Whether the bake reads and writes its cache: it names one and is not validated (a validated
// bake is one the layer watched: nothing is taken from the cache, and what the layer may yet
// fail is not put there).
bool usesCache(const BakeSettings& settings);
// The roughness of every mip of a `mips` chain from a `size` face, by the recipe's schedule.
std::vector<float> roughnessOfMips(const shading::ShadingRecipe& recipe, uint32_t mips, uint32_t size);
// roughness = mip / (mips - 1), as in the documents; mip 0 is the mirror (roughness 0).
float roughnessOfMip(uint32_t mip, uint32_t mips);

} // namespace iblkit::bake
