// `iblkit shading` as a user runs it: a small bench's page, results and plots, the reference kept
// in the cache and read back the second time, and one line for every name it does not know.
#include "read_file.hpp"
#include "run_process.hpp"
#include "temp_folder.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace iblkit::testing {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> shadingCommand(const TempFolder& folder, std::vector<std::string> more = {}) {
    std::vector<std::string> command = {IBLKIT_EXECUTABLE, "shading", "--out", (folder.path() / "docs/shading.md").string(),
                                        "--cache", (folder.path() / "cache").string(), "--cell-size", "8", "-q",
                                        "--environments", "sun-side", "--recipes", "kit,document"};
    command.insert(command.end(), more.begin(), more.end());
    return command;
}

TEST(ShadingCli, WritesThePageTheResultsAndThePlotsAndKeepsTheReference) {
    TempFolder folder;
    const auto first = runProcess(shadingCommand(folder));
    ASSERT_EQ(first.exitCode, 0) << first.err;
    const auto docs = folder.path() / "docs";
    for (const char* name : {"shading.md", "shading/results.json", "shading/summary.png", "shading/sun-side.png",
                             "shading/sun-side/reference.png", "shading/sun-side/kit-error.png"})
        EXPECT_TRUE(fs::exists(docs / name)) << name;
    const auto results = nlohmann::json::parse(readFile(docs / "shading/results.json"));
    const auto& environment = results.at("environments").at(0);
    EXPECT_EQ(environment.at("name"), "sun-side");
    ASSERT_EQ(environment.at("recipes").size(), 2u);
    EXPECT_EQ(environment.at("recipes").at(0).at("recipe"), "kit");
    EXPECT_EQ(environment.at("recipes").at(0).at("lights").size(), 1u) << "the sun, taken out";
    EXPECT_EQ(environment.at("recipes").at(1).at("lights").size(), 0u) << "the documents keep it in the maps";
    EXPECT_EQ(environment.at("recipes").at(0).at("mean_relative_error").size(), 65u);
    EXPECT_EQ(results.at("grid").at("rows").size(), 5u);
    const auto page = readFile(docs / "shading.md");
    EXPECT_NE(page.find("| kit |"), std::string::npos);
    EXPECT_EQ(page.find("(from the cache)"), std::string::npos);
    const auto second = runProcess(shadingCommand(folder));
    ASSERT_EQ(second.exitCode, 0) << second.err;
    EXPECT_NE(readFile(docs / "shading.md").find("(from the cache)"), std::string::npos);
    // The same reference, the same numbers; only the bakes' times differ.
    const auto withoutTimes = [](nlohmann::json json) {
        for (auto& recipe : json.at("environments").at(0).at("recipes")) recipe.erase("bake_ms");
        return json;
    };
    EXPECT_EQ(withoutTimes(nlohmann::json::parse(readFile(docs / "shading/results.json"))), withoutTimes(results));
}

TEST(ShadingCli, RefusesAnUnknownRecipeOrEnvironmentInOneLine) {
    TempFolder folder;
    for (const auto& [option, value, expected] :
         {std::tuple{"--recipes", "phong", "no shading recipe 'phong'"}, std::tuple{"--environments", "mars", "no environment 'mars'"}}) {
        const auto result = runProcess(shadingCommand(folder, {option, value}));
        EXPECT_NE(result.exitCode, 0) << expected;
        EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_FALSE(fs::exists(folder.path() / "docs")) << expected;
    }
}

} // namespace
} // namespace iblkit::testing
