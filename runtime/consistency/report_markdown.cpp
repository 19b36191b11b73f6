#include "consistency_suite.hpp"
#include "vulkan_context.hpp"

#include <fmt/core.h>

#include <glslang/build_info.h>
#include <spirv-tools/libspirv.h>

namespace iblkit::consistency {
namespace {

std::string header(const vulkan::VulkanContext& context, const std::string& openGlRenderer, const SuiteOptions& options,
                   const std::string& command) {
    std::string text = "# Consistency: every kernel, in every form, against the C++ reference\n\n";
    text += fmt::format("Made by `{}`; do not edit.\n\n", command);
    const auto& device = context.deviceInfo();
    text += fmt::format("- Device: {} ({}, Vulkan {}), driver {}\n", device.name, device.type, device.apiVersion, device.driver);
    text += fmt::format("- OpenGL: {}\n", openGlRenderer);
    text += fmt::format("- glslang {}.{}.{}, SPIRV-Tools {}, Vulkan headers {}\n", GLSLANG_VERSION_MAJOR, GLSLANG_VERSION_MINOR,
                        GLSLANG_VERSION_PATCH, spvSoftwareVersionString(), VK_HEADER_VERSION);
    text += fmt::format("- {} samples per texel, the chunked kernels in dispatches of {}; the LUTs written as "
                        "R32G32_SFLOAT; the prefilters over a {}² procedural environment (sky, horizon, ground, a soft "
                        "sun of radiance ~40), sampled linearly at mip 0; the cube kernels over the same environment at "
                        "{}² (and as a {}×{} panorama), its mips made by DownsampleCubeCS's arithmetic\n",
                        options.sampleCount, options.chunkSamples, options.environmentSize, options.mipChainSize,
                        options.panoramaWidth, options.panoramaWidth / 2);
    text += "- Errors: the largest absolute error, the largest distance in float32 ULPs, the RMS error, and the count of "
            "NaN and infinite GPU values; against the C++ reference computed in float (f) and in double (g). "
            "A path passes when it has no NaN or infinity and its largest and RMS errors against both are within the "
            "bounds (max / RMS). The row \"f.\" is the float reference against the double one, shown for scale. "
            "PreviewCS, RenderReferenceCS, RenderReferenceSplitSumMaterialCS and SplitSumSpheresCS have no C++ reference: "
            "both columns of their rows are against path a.\n"
            "\n";
    return text;
}

std::string verdict(const ConsistencyRow& row) {
    if (!row.knownIssue.empty()) return row.passed ? "**yes, though known to diverge**" : "no, known (see the bounds)";
    return row.passed ? "yes" : "**no**";
}

std::string tableRow(const ConsistencyRow& row) {
    const auto judged = [&](std::string text) { return row.isReference ? std::string("—") : text; };
    const auto cell = [&](double value, const char* format) { return judged(fmt::format(fmt::runtime(format), value)); };
    return fmt::format("| {} | {} | {} | {} | {} | {} | {:.2e} | {:.0f} | {:.2e} | {} | {} | {} | {} |\n", row.kernel,
                       row.output, row.path, cell(row.vsFloat.maxAbsolute, "{:.2e}"), cell(row.vsFloat.maxUlp, "{:.0f}"),
                       cell(row.vsFloat.rms, "{:.2e}"), row.vsDouble.maxAbsolute, row.vsDouble.maxUlp, row.vsDouble.rms,
                       row.vsDouble.nonFinite, // both columns measure the same GPU values
                       judged(fmt::format("{:.1e} / {:.1e}", row.bounds.maxVsFloat, row.bounds.rmsVsFloat)),
                       judged(fmt::format("{:.1e} / {:.1e}", row.bounds.maxVsDouble, row.bounds.rmsVsDouble)),
                       judged(verdict(row)));
}

} // namespace

std::string renderMarkdown(const std::vector<ConsistencyRow>& rows, const vulkan::VulkanContext& context,
                           const std::string& openGlRenderer, const SuiteOptions& options, const std::string& command) {
    std::string text = header(context, openGlRenderer, options, command);
    text += "| kernel | output | path | max abs vs f | max ULP vs f | RMS vs f | max abs vs g | max ULP vs g | RMS vs g "
            "| NaN/Inf | bounds vs f | bounds vs g | pass |\n";
    text += "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& row : rows) text += tableRow(row);
    text += "\n## The bounds\n\n" + boundsRationale();
    return text;
}

} // namespace iblkit::consistency
