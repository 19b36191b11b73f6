// Every Vulkan path of the seed shaders computes what the C++ reference computes, within the
// bounds measured and explained in docs/consistency.md; deliberately broken shaders do not.
#include "consistency_suite.hpp"
#include "shader_paths.hpp"
#include "read_file.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace iblkit::consistency {
namespace {

namespace fs = std::filesystem;

// Small enough for the broken variants, which fail long before the sizes matter.
SuiteOptions testSizes(SuiteOptions options) {
    options.lutSizes = {32};
    options.prefilterSize = 16;
    return options;
}

// With validation on: anything the layer says fails the test.
std::vector<ConsistencyRow> run(const SuiteOptions& options) {
    auto log = std::make_shared<vulkan::ValidationLog>();
    std::vector<ConsistencyRow> rows;
    {
        const vulkan::VulkanContext context({"", true, log});
        rows = runConsistency(context, options).rows;
    }
    for (const auto& message : log->messages()) ADD_FAILURE() << "validation: " << message;
    return rows;
}

// The whole suite, as `iblkit consistency` runs it for docs/consistency.md (about 45 s).
TEST(Consistency, EveryPathIsWithinItsBoundsForEveryOutput) {
    const auto rows = run(defaultSuiteOptions());
    ASSERT_EQ(rows.size(), 6u * 6u) << "LUT 512² and 32², four prefilter roughnesses: the float reference and five paths each";
    EXPECT_EQ(std::count_if(rows.begin(), rows.end(), [](const auto& row) { return row.path == openGlPathName(); }), 6)
        << "path d runs on OpenGL for every output";
    for (const auto& row : rows) {
        if (row.isReference) continue;
        EXPECT_TRUE(row.passed) << row.output << " / " << row.path << ": max " << row.vsFloat.maxAbsolute << " vs float, "
                                << row.vsDouble.maxAbsolute << " vs double; RMS " << row.vsFloat.rms << ", "
                                << row.vsDouble.rms;
        EXPECT_EQ(row.vsFloat.nonFinite, 0u) << row.output << " / " << row.path;
    }
}

// A copy of hlsl/ with one change, compiled through the same paths.
class BrokenVariant : public ::testing::Test {
protected:
    SuiteOptions broken(const std::string& file, const std::string& faithful, const std::string& brokenText) {
        fs::copy("hlsl", scratch.path() / "hlsl", fs::copy_options::recursive);
        const auto path = scratch.path() / "hlsl" / file;
        std::string source = testing::readFile(path);
        const auto at = source.find(faithful);
        EXPECT_NE(at, std::string::npos) << "the faithful text to break is no longer in " << file;
        source.replace(at, faithful.size(), brokenText);
        std::ofstream(path) << source;
        auto options = testSizes(defaultSuiteOptions((scratch.path() / "hlsl" / "shaders.json").string()));
        options.roughnesses = {0.25f, 0.5f};
        return options;
    }

    static void expectEveryPathFails(const std::vector<ConsistencyRow>& rows, const std::string& output) {
        size_t failedPaths = 0, paths = 0;
        for (const auto& row : rows)
            if (!row.isReference && row.output.rfind(output, 0) == 0) {
                ++paths;
                failedPaths += !row.passed;
            }
        EXPECT_GT(paths, 0u);
        EXPECT_EQ(failedPaths, paths) << "a broken " << output << " passed the comparison on some path";
    }

    testing::TempFolder scratch;
};

TEST_F(BrokenVariant, KFromDirectLightingFailsTheLut) {
    const auto rows = run(broken("Common/PBR.fxh", "float k = ( a * a ) / 2.f;", "float k = ( ( a + 1.f ) * ( a + 1.f ) ) / 8.f;"));
    expectEveryPathFails(rows, "LUT");
}

TEST_F(BrokenVariant, TransposedTangentFrameFailsThePrefilter) {
    const auto rows = run(broken("Common/PBR.fxh", "return normalize( mul( h, toWorld ) );", "return normalize( mul( toWorld, h ) );"));
    expectEveryPathFails(rows, "prefilter");
}

TEST_F(BrokenVariant, SwappedCubeFaceFailsThePrefilter) {
    const auto rows = run(broken("PrefilterSpecularCS.hlsl", "normal = float3( uv.x, 1.f, -uv.y );", "normal = float3( uv.x, -1.f, uv.y );"));
    expectEveryPathFails(rows, "prefilter");
}

} // namespace
} // namespace iblkit::consistency

namespace iblkit::consistency {
namespace {

// docs/consistency.md is the output of the command it names, committed; the numbers depend on
// the machine, the shape does not.
TEST(CommittedReport, IsTheCommandsOutputWithEveryPathWithinItsBounds) {
    const std::string report = testing::readFile("docs/consistency.md");
    ASSERT_FALSE(report.empty()) << "docs/consistency.md is missing; run: iblkit consistency --out docs/consistency.md";
    EXPECT_NE(report.find("Made by `iblkit consistency --out docs/consistency.md`"), std::string::npos);
    for (const char* output : {"| LUT 512² |", "| LUT 32² |", "| prefilter 32² r=0 |", "| prefilter 32² r=0.25 |",
                               "| prefilter 32² r=0.5 |", "| prefilter 32² r=1 |"})
        for (const auto path : kVulkanPaths) {
            EXPECT_NE(report.find(std::string(output) + " " + std::string(pathName(path)) + " |"), std::string::npos)
                << output << " " << pathName(path);
            EXPECT_NE(report.find(std::string(output) + " " + std::string(openGlPathName()) + " |"), std::string::npos)
                << output << " on OpenGL";
        }
    EXPECT_EQ(report.find("**no**"), std::string::npos) << "a row of the committed report is outside its bounds";
    EXPECT_NE(report.find(boundsRationale()), std::string::npos) << "the report's bounds are not the suite's";
}

} // namespace
} // namespace iblkit::consistency
