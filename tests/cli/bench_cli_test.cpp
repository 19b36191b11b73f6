// `iblkit bench` as a user runs it: the CSV, JSON, plots and Markdown report of a tiny run, and
// one line with a non-zero exit for bad arguments.
#include "bake_cli_fixture.hpp"
#include "read_file.hpp"
#include "run_process.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace iblkit::testing {
namespace {

namespace fs = std::filesystem;

class BenchCli : public ::testing::Test {
protected:
    ProcessResult iblkit(std::vector<std::string> arguments, std::vector<std::string> environment = {}) const {
        arguments.insert(arguments.begin(), IBLKIT_EXECUTABLE);
        for (const char* flag : {"--size", "32", "--lut-size", "16", "--texels", "16", "--repeat", "1",
                                 "--irradiance-size", "4", "--cache"})
            arguments.push_back(flag);
        arguments.push_back((scratch.path() / "cache").string());
        return runProcess(arguments, environment);
    }
    std::string at(const std::string& name) const { return (scratch.path() / name).string(); }
    TempFolder scratch;
};

TEST_F(BenchCli, WritesResultsPlotsAndReport) {
    const auto result = iblkit({"bench", "sky", "sun", "--samples", "16,256", "--lut-nodes", "7", "--lut-grid", "16", "--lut-degree", "3", "--out", at("bench"), "--markdown",
                                at("bench.md")});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_NE(result.err.find("bench  specular"), std::string::npos) << "progress goes to stderr";
    const auto json = nlohmann::json::parse(readFile(scratch.path() / "bench" / "results.json"));
    EXPECT_EQ(json.at("results").size(), 5u + 2u * 4u * 2u + 2u)
        << "LUT x5 (document x2, quadrature x1, quadrature grid x1, polynomial x1), specular x2 per method (document, filtered, table, convolution) per "
           "environment, irradiance x2";
    EXPECT_EQ(json.at("device").get<std::string>().find("llvmpipe"), 0u);
    const auto csv = readFile(scratch.path() / "bench" / "results.csv");
    EXPECT_EQ(csv.rfind("output,environment,method,samples", 0), 0u);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 23 + 2 * 4 * 2 * 2) << "a row per result and per specular mip";
    for (const char* plot : {"specular_sky.png", "specular_sun.png", "specular_summary.png", "lut.png", "irradiance.png"}) {
        const auto png = readFile(scratch.path() / "bench" / plot);
        EXPECT_EQ(png.substr(1, 3), "PNG") << plot;
    }
    const auto report = readFile(scratch.path() / "bench.md");
    EXPECT_NE(report.find("llvmpipe"), std::string::npos);
    EXPECT_NE(report.find("](bench/specular_sky.png)"), std::string::npos) << "plots linked relative to the report";
    EXPECT_NE(report.find("Time to reach the targets"), std::string::npos);
    EXPECT_NE(report.find("| LUT (max) | "), std::string::npos) << "the time-error frontiers";
}

// The cost curve: whole `iblkit bake` processes at each size, for the default method and the
// documents', each with its time, its peak memory and its error at that size.
TEST_F(BenchCli, TheSizeCurveBakesWholeProcessesAtEachSize) {
    const auto result = iblkit({"bench", "sky", "sun", "--outputs", "bake", "--sizes", "32,64", "--out",
                                at("sizes"), "--markdown", at("sizes.md")});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_NE(result.err.find("'sun' has no file to bake"), std::string::npos) << result.err;
    const auto json = nlohmann::json::parse(readFile(scratch.path() / "sizes" / "results.json"));
    EXPECT_TRUE(json.at("bakes").empty()) << "the curve instead of the cache's and the plan's bakes";
    const auto& curve = json.at("size_curve");
    ASSERT_EQ(curve.size(), 4u) << "two sizes of the sky, two methods each";
    for (size_t row = 0; row < curve.size(); ++row) {
        const auto& point = curve[row];
        SCOPED_TRACE(point.dump());
        EXPECT_EQ(point["environment"], "sky");
        EXPECT_EQ(point["size"], row < 2 ? 32 : 64);
        EXPECT_EQ(point["method"], row % 2 == 0 ? "convolution" : "document");
        EXPECT_EQ(point["samples"], row % 2 == 0 ? 128 : 1024) << "each method's default count";
        EXPECT_GT(point["wall_ms"].get<double>(), 0);
        // A process that opens lavapipe maps LLVM: about 130 MiB at these sizes, never the bench's own.
        EXPECT_GT(point["peak_mib"].get<double>(), 20);
        EXPECT_LT(point["peak_mib"].get<double>(), 1024);
        EXPECT_GT(point["error_max"].get<double>(), point["error_rms"].get<double>());
    }
    for (const size_t convolution : {0u, 2u}) {
        EXPECT_LT(curve[convolution]["error_rms"].get<double>(), 0.01) << "the convolution within its target";
        EXPECT_GT(curve[convolution + 1]["error_rms"].get<double>(), 10 * curve[convolution]["error_rms"].get<double>())
            << "the documents' importance sampling, far noisier";
    }
    EXPECT_EQ(readFile(scratch.path() / "sizes" / "size_curve.png").substr(1, 3), "PNG");
    const auto report = readFile(scratch.path() / "sizes.md");
    EXPECT_NE(report.find("## Cost against size"), std::string::npos);
    EXPECT_NE(report.find("](sizes/size_curve.png)"), std::string::npos);
    EXPECT_NE(report.find("| sky | document | 1024 | 64² |"), std::string::npos) << report;
    EXPECT_NE(report.find("--outputs bake --sizes 32,64 --out"), std::string::npos) << "the command that makes the curve again";
}

TEST_F(BenchCli, SizesNeedTheBakeOutputAndPowersOfTwo) {
    for (const auto& [outputs, sizes] : {std::pair{"bake", "16,48"}, std::pair{"specular", "16"}}) {
        const auto result = iblkit({"bench", "sky", "--outputs", outputs, "--sizes", sizes, "--out", at("refused")});
        EXPECT_NE(result.exitCode, 0) << sizes;
        EXPECT_NE(result.err.find("--sizes"), std::string::npos) << result.err;
        EXPECT_FALSE(fs::exists(scratch.path() / "refused"));
    }
}

// A run that fails after its work, while writing (the plots cannot be drawn: a matplotlib that
// imports but has no pyplot), leaves the earlier results as they were and no partial folder.
TEST_F(BenchCli, AFailedRunLeavesEarlierResultsAsTheyWere) {
    const std::vector<std::string> tiny = {"bench", "sky", "--samples", "16", "--outputs", "specular", "--out", at("out")};
    ASSERT_EQ(iblkit(tiny).exitCode, 0);
    const auto before = snapshot(scratch.path() / "out");
    ASSERT_EQ(before.count("manifest.json"), 1u);
    scratch.write("fake-python/matplotlib/__init__.py", "");
    const auto failed = iblkit(tiny, {"PYTHONPATH=" + at("fake-python")});
    EXPECT_NE(failed.exitCode, 0);
    EXPECT_NE(failed.err.find("bench  specular   sky"), std::string::npos) << "the failure came after the work";
    EXPECT_NE(failed.err.find("could not draw the plots"), std::string::npos) << failed.err;
    EXPECT_EQ(snapshot(scratch.path() / "out"), before);
    for (const auto& entry : fs::directory_iterator(scratch.path()))
        EXPECT_EQ(entry.path().filename().string().find(".iblkit-partial"), std::string::npos) << entry.path();
}

// The folder is the bench's own: a user's files, or another command's output, are refused before
// the run and kept; an earlier bench's output is replaced.
TEST_F(BenchCli, AFolderOfOtherFilesIsRefusedBeforeTheRun) {
    const auto notes = scratch.write("notes/todo.txt", "keep me");
    const auto result = iblkit({"bench", "sky", "--samples", "16", "--outputs", "specular", "--out", at("notes")});
    EXPECT_NE(result.exitCode, 0);
    EXPECT_NE(result.err.find("is a folder with other files"), std::string::npos) << result.err;
    EXPECT_EQ(result.err.find("bench  specular"), std::string::npos) << "refused before any work";
    EXPECT_EQ(readFile(notes), "keep me");
    scratch.write("bake/manifest.json", R"({"generator": "iblkit", "command": "bake", "files": []})");
    const auto overBake = iblkit({"bench", "sky", "--samples", "16", "--outputs", "specular", "--out", at("bake")});
    EXPECT_NE(overBake.err.find("holds the output of iblkit bake"), std::string::npos) << overBake.err;
}

TEST_F(BenchCli, BadArgumentsGetOneLineAndNothingIsWritten) {
    for (const auto& arguments : std::vector<std::vector<std::string>>{
             {"bench", "nowhere.exr", "--out", at("out")},
             {"bench", "--samples", "0", "--out", at("out")},
             {"bench", "--method", "guess", "--out", at("out")},
             {"bench", "--size", "100", "--out", at("out")},
             {"bench", "--outputs", "everything", "--out", at("out")},
             {"bench", "--irradiance-size", "0", "--out", at("out")},
             {"bench", "furnace", "--out", at("out"), "--markdown", at("no-such-folder/bench.md")}}) {
        const auto result = iblkit(arguments);
        EXPECT_NE(result.exitCode, 0) << arguments[1];
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_FALSE(fs::exists(at("out"))) << arguments[1];
    }
}

// `--markdown` naming the bench's own input environment once overwrote it after the run.
TEST_F(BenchCli, AnOutputThatIsTheInputIsRefusedAndTheInputKept) {
    const auto environment = scratch.write("sky.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n\x80\x80\x80\x81\x80\x80\x80\x81");
    const auto before = readFile(environment);
    const auto result = iblkit({"bench", environment.string(), "--out", at("out"), "--markdown", environment.string()});
    EXPECT_NE(result.exitCode, 0);
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find(environment.filename().string()), std::string::npos) << result.err;
    EXPECT_EQ(readFile(environment), before);
    EXPECT_FALSE(fs::exists(at("out")));
}

} // namespace
} // namespace iblkit::testing
