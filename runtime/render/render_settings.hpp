#pragma once

#include "shading/shading_recipe.hpp"
#include "context_options.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

namespace iblkit::render {

// Pixels per cell of the sphere grid (sphere_grid.hpp).
inline constexpr uint32_t kDefaultCellSize = 48;
inline constexpr uint32_t kMinCellSize = 8;
// The reference's dispatch is one thread per active pixel in groups of 64, at most 65535 groups:
// 4,194,240 pixels, and the default grid at 192-pixel cells is 2496 x 960.
inline constexpr uint32_t kMaxCellSize = 192;

// The reference renders in batches, each over the pixels still short of the bound
// (kDefaultStandardErrorBound of their value): a pixel stops once within it, never before
// kMinSamples (so that a rare bright path has had its chances to show in the variance), never past
// --samples. A batch is kBatchSamples paths a pixel, more as fewer pixels remain (up to
// kMaxBatchSamples), run as dispatches within llvmpipe's loop budget (reference_render.hpp). At
// 2 % a pixel's noise moves a sphere's mean error by about 1.6 % at most.
inline constexpr uint32_t kBatchSamples = 64;
inline constexpr uint32_t kMaxBatchSamples = 16384;
inline constexpr uint32_t kMinSamples = 256;
inline constexpr uint32_t kDefaultMaxSamples = 1u << 20;
inline constexpr uint32_t kMaxSamples = 1u << 20;
inline constexpr double kDefaultStandardErrorBound = 0.02;
inline constexpr double kMinStandardErrorBound = 0.001, kMaxStandardErrorBound = 0.5;
// Relative errors, and standard errors, are taken against max(value, this share of the
// environment's mean radiance), so that a pixel the environment leaves nearly black (rough glass
// in the document's model, which absorbs what it reflects inside) does not turn noise into large
// ratios.
inline constexpr double kRelativeFloor = 0.1;

// The reference's BSDF: the path tracer document's as ported, or the same with the split sum's
// choices of k and of the diffuse weight (hlsl/Common/SplitSumMaterial.fxh), which leaves the
// split sum's approximation alone in the error. Named as RenderReferenceCS's methods.
enum class ReferenceBsdf { Document, SplitSum };
std::string_view methodOf(ReferenceBsdf bsdf);
// "document" or "split-sum", as --bsdf and errors.json name it.
std::string_view nameOf(ReferenceBsdf bsdf);
// The ReferenceBsdf of nameOf; throws RenderError for anything else.
ReferenceBsdf referenceBsdfNamed(std::string_view name);

struct RenderSettings {
    std::optional<std::filesystem::path> environment; // empty: the built-in sky
    std::optional<std::filesystem::path> lights;      // a lights file (lights_file.hpp)
    std::optional<std::filesystem::path> cache;       // the bake's content store
    std::filesystem::path outputDir;
    uint32_t maxSamples = kDefaultMaxSamples;
    double standardErrorBound = kDefaultStandardErrorBound;
    ReferenceBsdf bsdf = ReferenceBsdf::Document;
    shading::ShadingRecipe recipe = shading::defaultRecipe(); // how the split sum's maps are made and read
    uint32_t cellSize = kDefaultCellSize;
    uint32_t seed = 1;
    bool sanitize = false; // as the bake's --sanitize and --strict
    bool strict = false;
    // The split sum alone: no reference, so no errors; for a quick look, or for comparing the
    // split sum with another renderer's.
    bool splitSumOnly = false;
    vulkan::ContextOptions context;
};

// Throws RenderError naming the first setting out of range.
void validateSettings(const RenderSettings& settings);

} // namespace iblkit::render
