#include "render_settings.hpp"

#include "render_error.hpp"

#include <fmt/core.h>

namespace iblkit::render {

std::string_view methodOf(ReferenceBsdf bsdf) {
    return bsdf == ReferenceBsdf::Document ? "document" : "split-sum-material";
}

std::string_view nameOf(ReferenceBsdf bsdf) { return bsdf == ReferenceBsdf::Document ? "document" : "split-sum"; }

ReferenceBsdf referenceBsdfNamed(std::string_view name) {
    for (const auto bsdf : {ReferenceBsdf::Document, ReferenceBsdf::SplitSum})
        if (name == nameOf(bsdf)) return bsdf;
    throw RenderError(fmt::format("--bsdf {}: expected document or split-sum", name));
}

void validateSettings(const RenderSettings& settings) {
    if (settings.outputDir.empty()) throw RenderError("no output folder (-o DIR)");
    if (settings.maxSamples < kMinSamples || settings.maxSamples > kMaxSamples)
        throw RenderError(fmt::format("--samples {} is out of range: the reference takes {} to {} samples per pixel",
                                      settings.maxSamples, kMinSamples, kMaxSamples));
    if (!(settings.standardErrorBound >= kMinStandardErrorBound && settings.standardErrorBound <= kMaxStandardErrorBound))
        throw RenderError(fmt::format("--max-standard-error {} is out of range: {} to {}", settings.standardErrorBound,
                                      kMinStandardErrorBound, kMaxStandardErrorBound));
    if (settings.cellSize < kMinCellSize || settings.cellSize > kMaxCellSize)
        throw RenderError(fmt::format("--cell-size {} is out of range: {} to {} pixels", settings.cellSize, kMinCellSize, kMaxCellSize));
    if (settings.sanitize && settings.strict) throw RenderError("--sanitize and --strict cannot be given together");
}

} // namespace iblkit::render
