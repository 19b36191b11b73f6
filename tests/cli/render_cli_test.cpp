// `iblkit render` as a user runs it: a small render's files and its errors.json, and one line and
// nothing written for every input it refuses, an earlier render left as it was.
#include "read_file.hpp"
#include "run_process.hpp"
#include "temp_folder.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace iblkit::testing {
namespace {

namespace fs = std::filesystem;

// A 64 x 32 panorama of radiance 1, uncompressed RGBE.
fs::path whitePanorama(const TempFolder& folder) {
    std::string text = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 32 +X 64\n";
    for (int i = 0; i < 64 * 32; ++i) text += std::string("\x80\x80\x80\x81", 4);
    return folder.write("white.hdr", text);
}

// A small, quick render; `options` replace its defaults.
std::vector<std::string> renderCommand(const fs::path& environment, const fs::path& output,
                                       std::map<std::string, std::string> options = {}) {
    options.try_emplace("--cell-size", "9");
    options.try_emplace("--max-standard-error", "0.05");
    std::vector<std::string> command = {IBLKIT_EXECUTABLE, "render", environment.string(), "-o", output.string(), "-q"};
    for (const auto& [option, value] : options) command.insert(command.end(), {option, value});
    return command;
}

// The split sum alone, at the small render's cell size.
std::vector<std::string> splitSumOnlyCommand(const fs::path& environment, const fs::path& output) {
    return {IBLKIT_EXECUTABLE, "render", environment.string(), "-o", output.string(), "-q", "--cell-size", "9", "--split-sum-only"};
}

TEST(RenderCli, WritesBothImagesTheErrorMapAndTheTableOrTheSplitSumAlone) {
    TempFolder folder;
    const auto environment = whitePanorama(folder);
    const auto output = folder.path() / "render";
    const auto result = runProcess(renderCommand(environment, output));
    ASSERT_EQ(result.exitCode, 0) << result.err;
    for (const char* name : {"reference.png", "reference.exr", "standard_error.exr", "splitsum.png", "splitsum.exr",
                             "error.png", "errors.json", "manifest.json"})
        EXPECT_TRUE(fs::exists(output / name)) << name;
    const auto errors = nlohmann::json::parse(readFile(output / "errors.json"));
    EXPECT_EQ(errors.at("spheres").size(), 65u) << "13 roughnesses by plastic, half-metal, gold, silver and glass";
    EXPECT_EQ(errors.at("reference").at("converged"), true);
    EXPECT_LE(errors.at("reference").at("max_relative_standard_error").get<double>(), 0.05);
    EXPECT_EQ(errors.at("spheres").at(64).at("material"), "glass");
    EXPECT_EQ(errors.at("grid").at("roughness").size(), 13u);
    EXPECT_EQ(errors.at("recipe"), "kit");
    EXPECT_GT(errors.at("spheres").at(0).at("pixels").get<int>(), 40);

    // The split sum alone: the same image, the same grid, nothing of a reference.
    const auto alone = folder.path() / "alone";
    const auto aloneResult = runProcess(splitSumOnlyCommand(environment, alone));
    ASSERT_EQ(aloneResult.exitCode, 0) << aloneResult.err;
    std::vector<std::string> written;
    for (const auto& entry : fs::directory_iterator(alone)) written.push_back(entry.path().filename().string());
    std::sort(written.begin(), written.end());
    EXPECT_EQ(written, (std::vector<std::string>{"errors.json", "manifest.json", "splitsum.exr", "splitsum.png"}));
    EXPECT_EQ(readFile(alone / "splitsum.exr"), readFile(output / "splitsum.exr"));
    const auto aloneErrors = nlohmann::json::parse(readFile(alone / "errors.json"));
    EXPECT_EQ(aloneErrors.at("grid"), errors.at("grid"));
    EXPECT_EQ(aloneErrors.at("exposure"), errors.at("exposure"));
    EXPECT_FALSE(aloneErrors.contains("reference"));
    EXPECT_FALSE(aloneErrors.contains("spheres"));
}

TEST(RenderCli, RefusesBadInputInOneLineAndWritesNothing) {
    TempFolder folder;
    const auto environment = whitePanorama(folder);
    const auto output = folder.path() / "render";
    const auto refused = [&](const std::map<std::string, std::string>& options, const std::string& expected) {
        const auto result = runProcess(renderCommand(environment, output, options));
        EXPECT_NE(result.exitCode, 0) << expected;
        EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_FALSE(fs::exists(output)) << expected;
    };
    refused({{"--samples", "0"}}, "--samples 0 is out of range");
    const auto noFolder = runProcess(splitSumOnlyCommand(environment, ""));
    EXPECT_NE(noFolder.exitCode, 0);
    EXPECT_NE(noFolder.err.find("no output folder (-o DIR)"), std::string::npos) << noFolder.err;
    refused({{"--cell-size", "4"}}, "--cell-size 4 is out of range");
    refused({{"--max-standard-error", "0"}}, "--max-standard-error 0 is out of range");
    refused({{"--lights", (folder.path() / "none.json").string()}}, "does not exist");
    refused({{"--lights", folder.write("bad.json", R"({"lights": [{"type": "spot"}]})").string()}}, "unknown type \"spot\"");
    refused({{"--bsdf", "phong"}}, "--bsdf");
    refused({{"--recipe", "phong"}}, "--recipe no shading recipe 'phong'");
    refused({{"--samples", "256"}, {"--max-standard-error", "0.001"}}, "did not converge in 256 samples per pixel");
    // A texel of 7.4e19 passes the bake's bound (1e20), but the reference's sums of squares
    // overflow: more samples cannot help, and the message once advised them.
    std::string bright = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 32 +X 64\n";
    for (int i = 0; i < 64 * 32; ++i) bright += i == 700 ? std::string("\x80\x80\x80\xC3", 4) : std::string("\x80\x80\x80\x81", 4);
    const auto overflowed = runProcess(renderCommand(folder.write("bright.hdr", bright), output, {{"--samples", "256"}}));
    EXPECT_NE(overflowed.exitCode, 0);
    EXPECT_NE(overflowed.err.find("the reference's float sums overflowed"), std::string::npos) << overflowed.err;
    EXPECT_EQ(overflowed.err.find("raise --samples"), std::string::npos) << overflowed.err;
    EXPECT_FALSE(fs::exists(output));
    // The reference's options mean nothing without it.
    const std::map<std::string, std::string> referenceOptions = {
        {"--samples", "256"}, {"--max-standard-error", "0.1"}, {"--lights", environment.string()}, {"--bsdf", "document"},
        {"--seed", "2"}};
    for (const auto& [option, value] : referenceOptions) {
        auto command = splitSumOnlyCommand(environment, output);
        command.insert(command.end(), {option, value});
        const auto result = runProcess(command);
        EXPECT_NE(result.exitCode, 0) << option;
        EXPECT_NE(result.err.find(option + " excludes --split-sum-only"), std::string::npos) << result.err;
        EXPECT_FALSE(fs::exists(output)) << option;
    }
}

TEST(RenderCli, AFailedRenderLeavesTheEarlierOneAsItWas) {
    TempFolder folder;
    const auto environment = whitePanorama(folder);
    const auto output = folder.path() / "render";
    ASSERT_EQ(runProcess(renderCommand(environment, output)).exitCode, 0);
    const auto before = readFile(output / "errors.json");
    const auto failed = runProcess(renderCommand(environment, output, {{"--samples", "256"}, {"--max-standard-error", "0.001"}}));
    EXPECT_NE(failed.err.find("did not converge"), std::string::npos) << failed.err;
    EXPECT_EQ(readFile(output / "errors.json"), before);
    const auto notARender = folder.write("notes/todo.txt", "keep me");
    const auto result = runProcess(renderCommand(environment, notARender.parent_path()));
    EXPECT_NE(result.err.find("other files"), std::string::npos) << result.err;
    EXPECT_EQ(readFile(notARender), "keep me");
}

// render-report made quick: the sky alone, small cells, a loose bound.
std::vector<std::string> quickReportCommand(const fs::path& page, std::map<std::string, std::string> options = {}) {
    for (const auto& [option, value] : std::map<std::string, std::string>{
             {"--environments", "sky"}, {"--cell-size", "8"}, {"--samples", "256"}, {"--max-standard-error", "0.5"}})
        options.try_emplace(option, value);
    std::vector<std::string> command = {IBLKIT_EXECUTABLE, "render-report", "--out", page.string(), "-q"};
    for (const auto& [option, value] : options) command.insert(command.end(), {option, value});
    return command;
}

TEST(RenderReportCli, AQuickPageWithItsPicturesNamesTheCommandThatMadeIt) {
    TempFolder folder;
    const auto page = folder.path() / "docs" / "errors.md";
    fs::create_directories(page.parent_path());
    const auto result = runProcess(quickReportCommand(page));
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const auto text = readFile(page);
    EXPECT_NE(text.find("--environments sky --cell-size 8 --samples 256 --max-standard-error 0.5`"), std::string::npos)
        << text.substr(0, 400);
    EXPECT_NE(text.find("## sky"), std::string::npos);
    std::vector<std::string> pictures;
    for (const auto& entry : fs::directory_iterator(page.parent_path() / "split-sum" / "sky"))
        pictures.push_back(entry.path().filename().string());
    std::sort(pictures.begin(), pictures.end());
    EXPECT_EQ(pictures, (std::vector<std::string>{"error-document.png", "error-split-sum.png", "errors-document.json",
                                                  "errors-split-sum.json", "reference.png", "splitsum.png"}));
    // Every sphere of both tables is in the page, as errors.json has it.
    const auto errors = nlohmann::json::parse(readFile(page.parent_path() / "split-sum" / "sky" / "errors-document.json"));
    const double first = errors.at("spheres").at(0).at("mean_relative_error").get<double>();
    EXPECT_NE(text.find(fmt::format(" {:.1f} (", 100 * first)), std::string::npos);
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(page.parent_path())) left.push_back(entry.path().filename().string());
    EXPECT_EQ(left.size(), 2u) << "the page and split-sum/, nothing of the renders' own";
}

TEST(RenderReportCli, RefusesBeforeAnyRenderAndAFailedRunLeavesTheEarlierPage) {
    TempFolder folder;
    const auto page = folder.path() / "errors.md";
    ASSERT_EQ(runProcess(quickReportCommand(page)).exitCode, 0);
    const auto earlierPage = readFile(page);
    const auto earlierPicture = readFile(folder.path() / "split-sum" / "sky" / "reference.png");
    const auto expectUnchanged = [&] {
        EXPECT_EQ(readFile(page), earlierPage);
        EXPECT_EQ(readFile(folder.path() / "split-sum" / "sky" / "reference.png"), earlierPicture);
    };
    const auto refused = [&](const std::map<std::string, std::string>& options, const std::string& expected) {
        const auto result = runProcess(quickReportCommand(page, options));
        EXPECT_NE(result.exitCode, 0) << expected;
        EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        expectUnchanged();
    };
    refused({{"--environments", "sky,nowhere"}}, "no report environment 'nowhere'");
    refused({{"--cell-size", "4"}}, "--cell-size 4 is out of range");
    refused({{"--max-standard-error", "0.001"}}, "did not converge in 256 samples per pixel");
    // No scratch folder (TMPDIR names a file): one line naming it, before any render.
    const auto noScratch = runProcess(quickReportCommand(page), {"TMPDIR=" + page.string()});
    EXPECT_NE(noScratch.err.find("no scratch folder can be made: the system's temporary folder (TMPDIR '" + page.string() +
                                 "') is not usable"),
              std::string::npos)
        << noScratch.err;
    expectUnchanged();
    // split-sum/ is the report's own: a user's pictures there are not replaced, nor is a file of
    // that name, and both are refused before any render.
    TempFolder other;
    const auto user = other.write("split-sum/sky/reference.png", "a user's picture");
    const auto mine = runProcess(quickReportCommand(other.path() / "errors.md"));
    EXPECT_NE(mine.err.find("the pictures' folder: '" + (other.path() / "split-sum").string() + "' is a folder with other files"),
              std::string::npos)
        << mine.err;
    EXPECT_EQ(readFile(user), "a user's picture");
    EXPECT_FALSE(fs::exists(other.path() / "errors.md"));
    TempFolder third;
    third.write("split-sum", "a file where the pictures' folder goes");
    const auto file = runProcess(quickReportCommand(third.path() / "errors.md"));
    EXPECT_NE(file.err.find("exists and is not a folder"), std::string::npos) << file.err;
    const auto missing = runProcess(quickReportCommand(folder.path() / "missing" / "errors.md"));
    EXPECT_NE(missing.err.find("--out"), std::string::npos) << missing.err;
    EXPECT_FALSE(fs::exists(folder.path() / "missing"));
}

// Any manifest the kit wrote once passed as an earlier output: a render over a bake deleted the
// bake, and a bake over a render the render.
TEST(RenderCli, ABakesFolderIsNotARendersAndARendersNotABakes) {
    TempFolder folder;
    const auto environment = whitePanorama(folder);
    const auto bake = folder.path() / "bake", render = folder.path() / "render";
    ASSERT_EQ(runProcess({IBLKIT_EXECUTABLE, "bake", environment.string(), "-o", bake.string(), "--size", "16", "--no-cache", "-q"})
                  .exitCode,
              0);
    ASSERT_EQ(runProcess(splitSumOnlyCommand(environment, render)).exitCode, 0);
    const auto bakeManifest = readFile(bake / "manifest.json"), renderManifest = readFile(render / "manifest.json");
    const auto overBake = runProcess(splitSumOnlyCommand(environment, bake));
    EXPECT_NE(overBake.exitCode, 0);
    EXPECT_NE(overBake.err.find("holds the output of iblkit bake (its manifest.json says so), not of iblkit render"),
              std::string::npos)
        << overBake.err;
    const auto overRender =
        runProcess({IBLKIT_EXECUTABLE, "bake", environment.string(), "-o", render.string(), "--size", "16", "--no-cache", "-q"});
    EXPECT_NE(overRender.exitCode, 0);
    EXPECT_NE(overRender.err.find("holds the output of iblkit render"), std::string::npos) << overRender.err;
    EXPECT_EQ(readFile(bake / "manifest.json"), bakeManifest);
    EXPECT_EQ(readFile(render / "manifest.json"), renderManifest);
    EXPECT_EQ(runProcess(splitSumOnlyCommand(environment, render)).exitCode, 0) << "a render still replaces a render";
    const auto overInput = runProcess(splitSumOnlyCommand(environment, folder.path()));
    EXPECT_NE(overInput.err.find("overlap: the render would delete its own input"), std::string::npos) << overInput.err;
}

} // namespace
} // namespace iblkit::testing
