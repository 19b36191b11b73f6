#include "stress.hpp"

#include "bake_settings.hpp"

#include <fmt/core.h>

#include <map>
#include <tuple>

namespace iblkit::stress {
namespace {

const char* verdict(bool passed) { return passed ? "pass" : "**FAIL**"; }

std::string probeTable(const ProbeSweep& sweep) {
    std::string text = fmt::format(
        "PbrProbeCS evaluates each function of `Common/PBR.fxh` at {} arguments: every combination of N·V (or N·H) in "
        "{{0, the smallest denormal, 1e-7, 1e-4, 0.5, 1 − 1e-7, 1}}, roughness in {{0, the smallest denormal, 1e-4, "
        "0.01, 0.5, 1}}, and N·L, V·H (the GGX sample's ξ) in {{0, the smallest denormal, 1e-7, 0.5, 1 − 1e-7, 1}}; "
        "Hammersley at (i, n) for n from 1 to 2³² − 1. LutProbeCS evaluates the kit's LUT function at the {} (N·V, "
        "roughness) pairs. BsdfProbeCS evaluates the path tracer's functions (`document/Common/Bsdf.fxh`, "
        "`Sampling.fxh`, `Lights.fxh`, `Random.fxh`) at {} arguments: N·L and N·V in the set above, roughness in "
        "the set above and 0.02 and 0.05, V beside L and opposite it, metalness 0, 0.5 and 1; `iblkit render` calls "
        "them, and they are judged where it does: N·L and N·V from the smallest normal float (GPUs flush denormals), "
        "at the sphere grid's roughness from 0.05; its 0.02, where α² = 1.6e-7 is below float's spacing at 1 and D "
        "cancels across the lobe's core, is reported, not judged (docs/stability-notes.md). A value is *singular in "
        "the math* where the C++ double is NaN/Inf, *singular in float* "
        "where the C++ float (the shader's arithmetic) is and the double is not; the paths' values there are listed "
        "below, not judged. Everywhere else a path must have no NaN/Inf, and its error against the double, where a "
        "bake (for the path tracer's, the render) calls the function, must be within the bound.\n\n",
        sweep.pbrArguments, sweep.lutArguments, sweep.bsdfArguments);
    text += "| kernel | function | path | values | singular in the math | singular in float | NaN/Inf elsewhere | max "
            "error vs double where a bake calls it | bound | at the other arguments | |\n"
            "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& row : sweep.rows)
        text += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {:.3g}{} | {:.3g} | {:.3g} | {} |\n", row.kernel,
                            row.function, row.path,
                            row.values, row.singularInMath, row.singularInFloat, row.nonFinite, row.maxError,
                            row.relative ? " (relative)" : "", row.bound, row.maxErrorElsewhere, verdict(row.passed));
    text += fmt::format(
        "\nWhere a bake calls each function: the documents' LUT kernels at texel centres, N·V and roughness ≥ "
        "0.5 / {} (the largest LUT); the prefilter kernels that call D (PrefilterFilteredCS, PrefilterConvolutionCS) at "
        "the roughness of mip 1 or above, ≥ {:.4g} for the largest cube (tests/bake/document_inputs_test.cpp checks "
        "both); the render calls the path tracer's at roughness ≥ 0.02, N·L and N·V > 0 (judged from 0.05). Every "
        "singular point, and "
        "whether a bake or the render reaches it (it must not):\n\n"
        "| function | arguments | double | float | called by a bake |\n|---|---|---|---|---|\n",
        bake::kMaxLutSize, bake::roughnessOfMip(1, 15));
    for (const auto& point : sweep.singular)
        text += fmt::format("| {} | {} | {} | {} | {} |\n", point.function, point.arguments, point.inMath, point.inFloat,
                            point.calledByBake ? "**yes**" : "no");
    return text;
}

// Per environment and kernel: the worst output and path.
std::string environmentTable(const std::vector<EnvironmentRow>& rows) {
    struct Worst {
        size_t rows = 0, nonFinite = 0;
        double error = 0, bound = 0;
        std::string path, output;
        bool passed = true;
    };
    std::vector<std::tuple<std::string, uint32_t, std::string>> order;
    std::map<std::tuple<std::string, uint32_t, std::string>, Worst> worst;
    for (const auto& row : rows) {
        const auto key = std::tuple(row.environment, row.size, row.kernel);
        if (!worst.contains(key)) order.push_back(key);
        auto& entry = worst[key];
        ++entry.rows;
        entry.nonFinite += row.nonFinite;
        entry.bound = row.bound;
        entry.passed = entry.passed && row.passed;
        if (row.knownIssue.empty() && row.relativeError >= entry.error) {
            entry.error = row.relativeError;
            entry.path = row.path;
            entry.output = row.output;
        }
    }
    std::string text =
        "Every output of the consistency suite that reads an environment, on every path (the C++ float reference "
        "and the five forms), with the prefilter kernels at roughness 0, the smallest denormal, 1e-4, 0.01, 0.5 and "
        "1. The error is the largest against the C++ double over the double's largest value, both over the colour "
        "values (the first three of every four: an alpha of 1, or the harmonics' solid angle, would hide a dim "
        "environment's errors), the absolute error where they are all 0; PreviewCS, RenderReferenceCS, "
        "RenderReferenceSplitSumMaterialCS and SplitSumSpheresCS have no C++ reference and are compared with path a (the Monte Carlo references' OpenGL form rounds sin, cos and sqrt otherwise and its paths "
        "carry it into the sums: 1.4e-4 of the largest, with the suite's lights on a black environment). One line per "
        "environment and kernel, with its worst output and path (the rows of a known divergence, none now, are left "
        "out as in docs/consistency.md).\n\n"
        "| environment | cube | kernel | rows | NaN/Inf | worst error / largest value | where | bound | |\n"
        "|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& key : order) {
        const auto& [environment, size, kernel] = key;
        const auto& entry = worst.at(key);
        text += fmt::format("| {} | {}² | {} | {} | {} | {:.3g} | {}, {} | {:.3g} | {} |\n", environment, size, kernel,
                            entry.rows, entry.nonFinite, entry.error, entry.output, entry.path, entry.bound,
                            verdict(entry.passed));
    }
    return text;
}

// The rows of the consistency suite's known divergences that are past their bound: where the
// sweep sees the divergence, and how large it is.
std::string knownDivergenceTable(const std::vector<EnvironmentRow>& rows) {
    std::string text;
    size_t known = 0;
    for (const auto& row : rows) {
        if (row.knownIssue.empty()) continue;
        ++known;
        if (row.diverges())
            text += fmt::format("| {} | {}² | {} | {} | {} | {:.3g} | {:.3g} |\n", row.environment, row.size, row.kernel,
                                row.output, row.path, row.relativeError, row.bound);
    }
    if (known == 0) return "";
    const std::string shows = knownDivergencesShow(rows) ? "it shows, as it must"
                                                         : "**it no longer shows: the known divergence is stale**";
    return fmt::format("\nThe consistency suite's known divergences (docs/consistency.md says why) are judged "
                       "apart: each of their {} rows must be finite, and the divergence must show on some environment: "
                       "{}. Where it is past its bound:\n\n"
                       "| environment | cube | kernel | output | path | error / largest value | bound |\n"
                       "|---|---|---|---|---|---|---|\n",
                       known, shows) +
           text;
}

std::string growthTable(const std::vector<GrowthRow>& rows) {
    std::string text =
        "The documents' two estimators at growing sample counts, each against the same samples summed in double: "
        "largest absolute error. The documents' loop keeps one float accumulator per sum; past 2¹⁶ samples it drifts "
        "(the C++ column; its kernel cannot run there on llvmpipe, which ends loops after 65535 iterations). The "
        "kit's chunked kernels sum at most 32768 samples in a dispatch and add the chunks in an R32G32 accumulator, a "
        "two-level sum that stays at the float noise of a single chunk: that is the fix, and compensated sums inside "
        "a chunk would buy nothing a bake can store (an RGBA16F texel's half step is 2.4e-4 at 0.5).\n\n"
        "| output | samples | one float accumulator (C++) | the documents' kernel, Vulkan | chunked, Vulkan | "
        "chunked, OpenGL | NaN/Inf | bound | |\n|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& row : rows)
        text += fmt::format("| {} | {} | {:.3g} | {} | {:.3g} | {:.3g} | {} | {:.3g} | {} |\n", row.output, row.samples,
                            row.singleLoopFloat, row.documentKernel ? fmt::format("{:.3g}", *row.documentKernel) : "—",
                            row.chunkedVulkan, row.chunkedOpenGl, row.nonFinite, row.bound, verdict(row.passed));
    return text;
}

std::string inputTable(const std::vector<InputRow>& rows) {
    std::string text = "What the bake's loader does with a 64×32 panorama of radiance 1 and one such texel.\n\n"
                       "| input | policy | outcome | |\n|---|---|---|---|\n";
    for (const auto& row : rows)
        text += fmt::format("| {} | {} | {} | {} |\n", row.input, row.policy, row.outcome,
                            row.passed() ? (row.refused ? "refused, as it must be" : "pass") : "**FAIL**");
    return text;
}

} // namespace

std::string renderStabilityMarkdown(const StressReport& report, const vulkan::VulkanContext& context,
                                    const std::string& command) {
    std::string text = fmt::format(
        "# Numerical stability\n\nGenerated by `{}` on {} and {}. Each bound is twice the largest error measured on "
        "lavapipe, rounded up; why each error is what it is: docs/stability-notes.md. Overall: {}.\n\n",
        command, context.deviceInfo().name, report.openGlRenderer, report.passed() ? "every case passes" : "**FAILED**");
    text += "## PBR.fxh's functions at their edges\n\n" + probeTable(report.probes);
    text += "\n## Every cube kernel on extreme environments\n\n" + environmentTable(report.environments) +
            knownDivergenceTable(report.environments);
    text += "\n## Sums over many samples\n\n" + growthTable(report.sampleCounts);
    text += "\n## Inputs no kernel may see\n\n" + inputTable(report.inputs);
    return text;
}

} // namespace iblkit::stress
