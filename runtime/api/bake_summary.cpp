#include "api/bake_summary.hpp"

#include "api/baked_maps.hpp"

#include "bake_manifest.hpp"
#include "bake_progress.hpp"
#include "file_names.hpp"

#include <nlohmann/json.hpp>

namespace iblkit::api {
namespace {

nlohmann::json summaryJson(const bake::BakeSummary& summary) {
    nlohmann::json steps = nlohmann::json::array();
    const auto& kernels = summary.compiledKernels;
    for (const auto& step : summary.steps) {
        nlohmann::json entry{{"name", step.name}, {"device_ms", step.deviceMilliseconds}, {"wall_ms", step.wallMilliseconds},
                             {"peak_mib", step.peakMebibytes}};
        for (const auto& part : step.parts)
            entry["parts"].push_back({{"name", part.name}, {"device_ms", part.deviceMilliseconds}, {"wall_ms", part.wallMilliseconds}});
        steps.push_back(std::move(entry));
    }
    return {{"output", image_io::utf8Name(summary.outputDir)},
            {"device", summary.device},
            {"wall_ms", summary.wallMilliseconds},
            {"peak_mib", bake::peakResidentMebibytes()},
            {"steps", steps},
            {"files", bake::filesJson(summary.files)},
            {"sh_radiance", bake::coefficientsJson(summary.shRadiance)},
            {"clamped_values", bake::clampedValueCount(summary.halfRangeClamps)},
            {"half_range_clamps", bake::halfRangeClampsJson(summary.halfRangeClamps)},
            {"sanitized_texels", summary.sanitizedTexels},
            {"negative_texels", summary.negativeTexels.count},
            {"most_negative", summary.negativeTexels.mostNegative},
            {"cache", {{"hits", summary.cache.hits}, {"misses", summary.cache.misses}, {"damaged", summary.cache.corrupt}}},
            {"compiled_kernels", {{"hits", kernels.hits}, {"misses", kernels.misses}, {"stale", kernels.stale},
                                  {"damaged", kernels.damaged}, {"built_in", summary.kernelCompiles.builtIn},
                                  {"compiled", summary.kernelCompiles.compiled}, {"compile_ms", summary.kernelCompileMilliseconds}}},
            {"pipeline_cache_bytes", summary.pipelineCacheBytes},
            {"scene_notes", summary.sceneNotes}};
}

} // namespace

BakeSummary bakeSummaryOf(const bake::BakeSummary& summary) {
    BakeSummary result;
    result.folder = summary.outputDir;
    result.device = summary.device;
    for (const auto& step : summary.steps) result.steps.push_back({step.name, step.deviceMilliseconds, step.wallMilliseconds});
    result.wallMilliseconds = summary.wallMilliseconds;
    for (const auto& file : summary.files) result.files.push_back({file.name, file.sha256, file.bytes});
    result.shRadiance = shCoefficientsOf(summary.shRadiance);
    for (const auto& clamp : summary.halfRangeClamps)
        result.halfRangeClamps.push_back({clamp.texture, clamp.values, clamp.worstMip, clamp.worstShare});
    result.sanitizedTexels = summary.sanitizedTexels;
    result.negativeTexels = summary.negativeTexels.count;
    result.mostNegative = summary.negativeTexels.mostNegative;
    result.cache = {summary.cache.hits, summary.cache.misses, summary.cache.corrupt};
    result.cacheWarnings = summary.cacheWarnings;
    result.sceneNotes = summary.sceneNotes;
    const auto& kernels = summary.compiledKernels;
    result.compiledKernels = {kernels.hits, kernels.misses, kernels.stale, kernels.damaged};
    result.pipelineCacheBytes = summary.pipelineCacheBytes;
    result.json = summaryJson(summary).dump(2);
    return result;
}

} // namespace iblkit::api
