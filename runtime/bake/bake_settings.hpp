#pragma once

#include "kernels/sampled_methods.hpp"
#include "vulkan_context.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace iblkit::bake {

enum class LutFormat { Rg16Float, Rg32Float };

struct BakeSettings {
    std::optional<std::filesystem::path> environment; // empty: the built-in environment
    std::filesystem::path outputDir;
    std::optional<uint32_t> size;   // cube face size; default 256, or the input cube's own size
    std::optional<uint32_t> mips;   // specular mips; default: down to kSpecularFloor
    uint32_t samples = 1024;        // the documents' SAMPLE_COUNT, for the prefilter and the LUT
    uint32_t lutSize = 512;
    uint32_t lutSamples = 1024;
    LutFormat lutFormat = LutFormat::Rg16Float;
    uint32_t irradianceSize = 32;
    bool dds = false;
    bool exr = false;
    bool sanitize = false;  // replace NaN/Inf input texels by 0 instead of refusing them
    bool clampHalf = false; // clamp values beyond half range in 16-bit outputs instead of refusing them
    vulkan::ContextOptions context; // device selector and validation, as for every command
};

// Default specular chain: mips down to this face size, the last at roughness 1.
inline constexpr uint32_t kSpecularFloor = 8;
inline constexpr uint32_t kDefaultSize = 256;
// Sizes past these are refused before any work: a 16384² cube with its chain is ~8.6 GB as floats.
inline constexpr uint32_t kMaxCubeSize = 16384;
inline constexpr uint32_t kMaxLutSize = 16384;

// The face size the bake uses for a source of `inputCubeSize` (0 when the input is a panorama).
uint32_t resolvedSize(const BakeSettings& settings, uint32_t inputCubeSize);
// The specular mip count for a face size: the setting, or the chain down to kSpecularFloor.
uint32_t resolvedMips(const BakeSettings& settings, uint32_t size);
// Throws BakeError naming the first setting out of range.
void validateSettings(const BakeSettings& settings);
// roughness = mip / (mips - 1), as in the documents; mip 0 is the mirror (roughness 0).
float roughnessOfMip(uint32_t mip, uint32_t mips);

} // namespace iblkit::bake
