// iblkit stress's reduced set: every kernel at its numerical extremes, on every path, with no
// NaN/Inf and its errors against the C++ double within the bounds of docs/stability.md; a kit
// kernel broken at a singular point is caught.
#include "kernels/kernel_table.hpp"
#include "markdown_table.hpp"
#include "read_file.hpp"
#include "stress.hpp"
#include "temp_folder.hpp"
#include "vulkan_context.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace iblkit::stress {
namespace {

namespace fs = std::filesystem;

// The reduced sweep with the validation layer on (about 22 s). ctest runs every test in a
// process of its own, so one test checks everything the sweep's report must show.
struct ReducedRun {
    StressReport report;
    std::string markdown; // as `iblkit stress --reduced` writes it
};

ReducedRun reducedRun() {
    auto log = std::make_shared<vulkan::ValidationLog>();
    const vulkan::VulkanContext context({"", true, log});
    auto report = runStress(context, {true, {}});
    for (const auto& message : log->messages()) ADD_FAILURE() << "validation: " << message;
    auto markdown = renderStabilityMarkdown(report, context, "iblkit stress --reduced");
    return {std::move(report), std::move(markdown)};
}

// Every table row of a report under its table's header, with the cells that depend on the machine
// (measured errors and where they were worst) left out.
std::set<std::string> tableRows(const std::string& markdown) {
    static const std::set<std::string> measured{"max error vs double where a bake calls it", "at the other arguments",
                                                "worst error / largest value", "where", "one float accumulator (C++)",
                                                "the documents' kernel, Vulkan", "chunked, Vulkan", "chunked, OpenGL"};
    std::set<std::string> rows;
    std::vector<std::string> header;
    std::istringstream stream(markdown);
    std::string previous;
    for (std::string line; std::getline(stream, line); previous = line) {
        if (line.starts_with("|---")) header = testing::tableCells(previous);
        if (!line.starts_with("| ") || !line.ends_with("|")) continue;
        const auto cells = testing::tableCells(line);
        if (cells == header || cells.size() != header.size()) continue;
        std::string row = header.empty() ? "" : header.front();
        for (size_t i = 0; i < cells.size(); ++i)
            if (!measured.contains(header[i])) row += " | " + cells[i];
        rows.insert(row);
    }
    return rows;
}

void expectEveryCasePasses(const StressReport& report) {
    for (const auto& row : report.probes.rows)
        EXPECT_TRUE(row.passed) << row.function << " / " << row.path << ": " << row.nonFinite << " NaN/Inf, error "
                                << row.maxError << " (bound " << row.bound << ")";
    for (const auto& point : report.probes.singular)
        EXPECT_FALSE(point.calledByBake) << point.function << " is singular at " << point.arguments << ", which a bake reaches";
    for (const auto& row : report.environments)
        EXPECT_TRUE(row.passed) << row.environment << " " << row.size << "² / " << row.output << " / " << row.path << ": "
                                << row.nonFinite << " NaN/Inf, error " << row.relativeError << " (bound " << row.bound << ")";
    for (const auto& row : report.sampleCounts)
        EXPECT_TRUE(row.passed) << row.output << " at " << row.samples << " samples: " << row.chunkedVulkan << ", "
                                << row.chunkedOpenGl << " (bound " << row.bound << ")";
    for (const auto& row : report.inputs) EXPECT_TRUE(row.passed()) << row.input << " (" << row.policy << "): " << row.outcome;
    EXPECT_TRUE(knownDivergencesShow(report.environments))
        << "a known divergence of the consistency suite no longer shows in the sweep";
    EXPECT_TRUE(report.passed());
}

void expectEveryKernelSweptOnEveryPath(const StressReport& report) {
    std::vector<std::pair<std::string, std::string>> swept;
    for (const auto& row : report.environments) swept.emplace_back(row.kernel, row.path);
    for (const auto& row : report.probes.rows) swept.emplace_back(row.kernel, row.path);
    std::vector<std::string> paths{"f. C++ reference, float", std::string(consistency::openGlPathName())};
    for (const auto path : consistency::kVulkanPaths) paths.emplace_back(consistency::pathName(path));
    for (const auto& kernel : kernels::kernelTable())
        for (const auto& path : paths) {
            const bool againstPathA = kernel.name == "PreviewCS" || kernel.name.starts_with("RenderReference") ||
                                      kernel.name == "SplitSumSpheresCS";
            if (againstPathA && path.starts_with("f.")) continue; // no C++ reference: path a is its reference
            EXPECT_TRUE(std::any_of(swept.begin(), swept.end(), [&](const auto& each) {
                return each.first == kernel.name && each.second.starts_with(path);
            })) << kernel.name << " is not swept on " << path;
        }
}

// The documents' singular points are where the math says; the kit's LUT function has none.
void expectTheDocumentsSingularPoints(const StressReport& report) {
    const auto singularAt = [&](const std::string& function, const std::string& arguments) {
        return std::any_of(report.probes.singular.begin(), report.probes.singular.end(), [&](const auto& point) {
            return point.function.starts_with(function) && point.arguments == arguments;
        });
    };
    EXPECT_TRUE(singularAt("DistributionGGX", "c = 1, r = 0")) << "D's 0/0 at N.H = 1 and roughness 0";
    EXPECT_TRUE(singularAt("IntegrateBRDF", "c = 0, r = 0.5")) << "the visibility term's 0/0 at N.V = 0";
    EXPECT_FALSE(std::any_of(report.probes.singular.begin(), report.probes.singular.end(),
                             [](const auto& point) { return point.function.starts_with("IntegrateBrdfQuadrature"); }));
}

// Measured on lavapipe at 2^16 samples: one float accumulator is 7.6e-5 off the double sum, the
// chunked kernels 9.4e-6 (8 times less); at 2^20, 6.0e-3 against 6.2e-6.
void expectChunkedSumsToStayAtFloatNoise(const StressReport& report) {
    const auto& rows = report.sampleCounts;
    const auto at = std::find_if(rows.begin(), rows.end(), [](const auto& row) {
        return row.output.starts_with("LUT") && row.samples == 65536u;
    });
    ASSERT_NE(at, rows.end());
    EXPECT_GT(at->singleLoopFloat, 4 * std::max(at->chunkedVulkan, at->chunkedOpenGl));
}

TEST(Stress, TheReducedSweepPassesOnEveryPathForEveryKernel) {
    const auto [report, markdown] = reducedRun();
    {
        SCOPED_TRACE("every case passes");
        expectEveryCasePasses(report);
    }
    {
        SCOPED_TRACE("every kernel is swept on every path");
        expectEveryKernelSweptOnEveryPath(report);
    }
    {
        SCOPED_TRACE("the singular points are the documents' own");
        expectTheDocumentsSingularPoints(report);
    }
    {
        SCOPED_TRACE("chunked sums stay at float noise where one accumulator drifts");
        expectChunkedSumsToStayAtFloatNoise(report);
    }
    // docs/stability.md is the full sweep's report, committed: every row of this reduced run is in
    // it, with the same counts, bounds and verdicts (the errors depend on the machine). A report
    // left stale by a change to a kernel, a bound or a case is caught here.
    const std::string committed = testing::readFile("docs/stability.md");
    ASSERT_FALSE(committed.empty()) << "docs/stability.md is missing; run: iblkit stress --out docs/stability.md";
    EXPECT_NE(committed.find("Generated by `iblkit stress --out docs/stability.md`"), std::string::npos);
    EXPECT_NE(committed.find("Overall: every case passes."), std::string::npos);
    const auto committedRows = tableRows(committed), liveRows = tableRows(markdown);
    EXPECT_GT(liveRows.size(), 500u) << "the reduced report's tables were not read";
    size_t missing = 0;
    for (const auto& row : liveRows)
        if (!committedRows.contains(row) && ++missing <= 5) ADD_FAILURE() << "not in docs/stability.md: " << row;
    EXPECT_EQ(missing, 0u) << "docs/stability.md is stale: iblkit stress --out docs/stability.md";
    for (const char* world : {"city", "courtyard", "forest", "interior", "night", "studio", "sunrise", "sunset"})
        EXPECT_NE(committed.find("| " + std::string(world) + " | "), std::string::npos) << "the full sweep has Blender's " << world;
}

// A copy of hlsl/ whose LUT function lost its mirror limit: LutProbeCS returns NaN at roughness
// 0 on every path, and the sweep says so.
TEST(Stress, AKitKernelBrokenAtASingularPointFailsOnEveryPath) {
    testing::TempFolder scratch;
    fs::copy("hlsl", scratch.path() / "hlsl", fs::copy_options::recursive);
    const auto path = scratch.path() / "hlsl" / "Common" / "BrdfQuadrature.fxh";
    std::string source = testing::readFile(path);
    const std::string mirrorLimit = "if ( alpha2 < 1e-30f ) return float2( 1.f - fc, fc );";
    const auto found = source.find(mirrorLimit);
    ASSERT_NE(found, std::string::npos) << "the mirror limit is no longer in BrdfQuadrature.fxh";
    source.erase(found, mirrorLimit.size());
    std::ofstream(path) << source;

    const vulkan::VulkanContext context(vulkan::ContextOptions{});
    const opengl::EglContext gl;
    const auto options = consistency::defaultSuiteOptions((scratch.path() / "hlsl" / "shaders.json").string());
    consistency::SuiteRun run(context, gl, options);
    const auto sweep = sweepProbes(run);
    size_t failedPaths = 0;
    for (const auto& row : sweep.rows)
        if (row.kernel == "LutProbeCS" && !row.path.starts_with("f.")) failedPaths += row.nonFinite > 0 && !row.passed;
    EXPECT_EQ(failedPaths, 5u) << "four Vulkan paths and OpenGL";
}

} // namespace
} // namespace iblkit::stress
