// `iblkit porting --manifest`: every configuration of a user's code base is tried, in a child of
// its own, with a line each; a shader that explodes the frontend costs that shader, not the run;
// the report groups what failed by cause and the JSON says the same.
#include "read_file.hpp"
#include "run_process.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace iblkit::porting {
namespace {

// 2^26 copies of one token: glslang's preprocessor runs out of time or memory on it.
std::string macroBomb() {
    std::string text = "#define B0 x\n";
    for (int i = 1; i <= 26; ++i) text += "#define B" + std::to_string(i) + " B" + std::to_string(i - 1) + " B" + std::to_string(i - 1) + "\n";
    return text + "B26\n[numthreads(1, 1, 1)] void main() {}\n";
}

TEST(CodeBasePorting, EveryConfigurationIsTriedAndFailuresAreGroupedByCause) {
    iblkit::testing::TempFolder folder;
    const auto root = folder.path() / "Engine";
    folder.write("Engine/Shaders/Common/Math.hlsli", "float Twice(float x) { return 2.0 * x; }\n");
    folder.write("Engine/Shaders/Blur.hlsl", "#include \"Math.hlsli\"\nRWStructuredBuffer<float> Out : register(u0);\n"
                                             "[numthreads(RADIUS, 1, 1)] void CSMain(uint i : SV_DispatchThreadID) { Out[i] = Twice(i); }\n");
    folder.write("Engine/Shaders/Generic.hlsl", "struct V { float x; };\nV operator+(V a, V b) { V r; r.x = a.x + b.x; return r; }\n"
                                                "float4 PSMain() : SV_Target { return 1.0; }\n");
    folder.write("Engine/Shaders/Generic2.hlsl", "struct W { float x; };\nW operator+(W a, W b) { return a; }\n"
                                                 "float4 PSMain() : SV_Target { return 2.0; }\n");
    folder.write("Engine/Shaders/Bomb.hlsl", macroBomb());
    const auto manifest = folder.write("engine.json", R"({"name": "Engine", "repository": "https://example.org/engine",
      "commit": "0123456789abcdef0123", "include_dirs": ["Shaders/Common"],
      "configurations": [
        {"file": "Shaders/Blur.hlsl", "entry": "CSMain", "profile": "cs_6_0", "defines": {"RADIUS": "8"}},
        {"file": "Shaders/Generic.hlsl", "entry": "PSMain", "profile": "ps_6_0"},
        {"file": "Shaders/Generic2.hlsl", "entry": "PSMain", "profile": "ps_6_0"},
        {"file": "Shaders/Bomb.hlsl", "entry": "main", "profile": "cs_6_0"},
        {"file": "Shaders/Blur.hlsl", "entry": "Trace", "profile": "lib_6_3", "name": "trace"}]})");
    const auto json = folder.path() / "report.json", markdown = folder.path() / "report.md";
    const auto result = testing::runProcess({IBLKIT_EXECUTABLE, "porting", "--manifest", manifest.string(), "--source",
                                             root.string(), "--seconds", "2", "--json", json.string(), "--out",
                                             markdown.string()});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_NE(result.err.find("[1/5] Engine Blur.hlsl:CSMain:cs_6_0: every form"), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("[4/5] Engine Bomb.hlsl:main:cs_6_0: refused:"), std::string::npos) << result.err;
    EXPECT_NE(result.out.find("5 configurations (1 ray tracing or mesh): 1 of 4 reach SPIR-V, 1 every form"), std::string::npos)
        << result.out;
    const auto report = nlohmann::json::parse(testing::readFile(json));
    EXPECT_EQ(report["totals"]["spirv"], 1);
    EXPECT_EQ(report["totals"]["ray_tracing_or_mesh"], 1);
    // The two operator shaders share one cause, named in the kit's words without their places.
    ASSERT_GE(report["causes"].size(), 2u);
    EXPECT_EQ(report["causes"][0]["count"], 2);
    EXPECT_NE(report["causes"][0]["cause"].get<std::string>().find("operator overloading"), std::string::npos) << report["causes"][0];
    const auto& bomb = report["code_bases"][0]["configurations"][3];
    EXPECT_FALSE(bomb["spirv"].get<bool>());
    EXPECT_NE(bomb["error"].get<std::string>().find("the kit's compiler"), std::string::npos) << bomb["error"];
    const auto page = testing::readFile(markdown);
    EXPECT_NE(page.find("| [Engine](https://example.org/engine) | `0123456789ab` | 5 |"), std::string::npos) << page;
}

TEST(CodeBasePorting, AMissingCodeBaseIsOneLineNamingWhereItWasLookedFor) {
    iblkit::testing::TempFolder folder;
    const auto manifest = folder.write("engine.json", R"({"name": "Engine", "repository": "https://example.org/engine",
      "commit": "0123", "configurations": [{"file": "a.hlsl", "entry": "main", "profile": "cs_6_0"}]})");
    const auto result = testing::runProcess({IBLKIT_EXECUTABLE, "porting", "--manifest", manifest.string(), "--sources",
                                             (folder.path() / "nowhere").string()});
    EXPECT_NE(result.exitCode, 0);
    EXPECT_NE(result.err.find("the code base Engine is not on disk there (https://example.org/engine at 0123)"), std::string::npos)
        << result.err;
}

} // namespace
} // namespace iblkit::porting
