// Graphics run files as docs/run-files.md describes them, on Vulkan and on OpenGL: Direct3D's
// conventions (row 0 is NDC y = +1, SV_Position from the top, depth 0 to 1, clockwise fronts),
// vertex input and targets by semantic, and one line for each kind of bad draw.
#include "run_error.hpp"
#include "run_executor.hpp"
#include "run_file.hpp"
#include "temp_folder.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace iblkit::run {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A full-screen triangle made from SV_VertexID: each pixel writes its uv and SV_Position.
constexpr const char* kTriangleShader = R"(
cbuffer Params { float4 Tint; };
struct VSOut { float4 position : SV_Position; float2 uv : TEXCOORD0; };
VSOut VSMain(uint id : SV_VertexID) {
    VSOut o;
    const float2 uv = float2((id << 1) & 2, id & 2);
    o.uv = uv;
    o.position = float4(uv * float2(2, -2) + float2(-1, 1), 0.5, 1);
    return o;
}
float4 PSMain(VSOut i) : SV_Target { return float4(i.uv, i.position.xy) * Tint; }
)";

// A quad from vertex buffers, drawn twice by instance: the second moved right and nearer.
constexpr const char* kMeshShader = R"(
cbuffer Scene { float4 Offset; };
struct VSIn { float3 position : POSITION; float2 uv : TEXCOORD; uint instance : SV_InstanceID; };
struct VSOut { float4 position : SV_Position; float2 uv : TEXCOORD0; nointerpolation uint instance : INSTANCE; };
VSOut VSMain(VSIn v) {
    VSOut o;
    o.position = float4(v.position.xy + Offset.xy * v.instance, v.position.z - Offset.z * v.instance, 1);
    o.uv = v.uv;
    o.instance = v.instance;
    return o;
}
struct PSOut { float4 color : SV_Target0; uint id : SV_Target1; };
PSOut PSMain(VSOut i) { PSOut o; o.color = float4(i.uv, 0, 1); o.id = i.instance + 1; return o; }
)";

class Draws : public ::testing::Test {
protected:
    void SetUp() override {
        std::ofstream(folder / "triangle.hlsl") << kTriangleShader;
        std::ofstream(folder / "mesh.hlsl") << kMeshShader;
    }

    static json triangle() {
        return json::parse(R"({
            "vertex": {"shader": "triangle.hlsl", "entry": "VSMain"}, "pixel": {"shader": "triangle.hlsl", "entry": "PSMain"},
            "resources": {"Params": {"kind": "cbuffer", "members": {"Tint": [1, 1, 1, 1]}}},
            "draw": {"vertices": 3},
            "targets": {"SV_Target0": {"format": "rgba32f", "size": [4, 2]}}})");
    }

    // Two 3/4-wide quads, the second at x + 0.5 and depth 0.3 in front of the first's 0.7.
    static json mesh() {
        return json::parse(R"({
            "vertex": {"shader": "mesh.hlsl", "entry": "VSMain"}, "pixel": {"shader": "mesh.hlsl", "entry": "PSMain"},
            "resources": {"Scene": {"kind": "cbuffer", "members": {"Offset": [0.5, 0, 0.4, 0]}}},
            "vertex_input": {"POSITION": {"format": "rgb32f", "values": [-1, 1, 0.7,  0.5, 1, 0.7,  -1, -1, 0.7,  0.5, -1, 0.7]},
                             "TEXCOORD0": {"format": "rg32f", "values": [0, 0, 1, 0, 0, 1, 1, 1]}},
            "indices": [0, 1, 2, 2, 1, 3],
            "draw": {"instances": 2},
            "targets": {"SV_Target0": {"format": "rgba32f", "size": [8, 2]}, "SV_Target1": {"format": "r32ui", "size": [8, 2]},
                        "SV_Depth": {"clear": 1.0, "test": "less"}}})");
    }

    // Runs on `api`; returns whether every expectation (and comparison) passed, the report in `report`.
    bool run(const json& file, RunApi api, std::string& report) const {
        const auto path = folder / "draw.run.json";
        std::ofstream(path) << file.dump(2);
        std::ostringstream out;
        RunOptions options;
        options.api = api;
        options.validation = true;
        const bool passed = executeRun(readRunFile(path), options, out);
        report = out.str();
        return passed;
    }

    std::string errorOf(const json& file) const {
        try {
            std::string report;
            run(file, RunApi::Vulkan, report);
        } catch (const RunError& error) {
            return error.what();
        }
        return "no error";
    }

    testing::TempFolder scratch;
    const fs::path& folder = scratch.path();
};

TEST_F(Draws, AFullScreenTriangleHasDirect3DsRowsAndPixelCentresOnBothApis) {
    auto file = triangle();
    json expected = json::array();
    for (int row = 0; row < 2; ++row)
        for (int column = 0; column < 4; ++column)
            for (double value : {(column + 0.5) / 4, (row + 0.5) / 2, column + 0.5, row + 0.5}) expected.push_back(value);
    // Interpolated uv is within 4 ulp of the pixel centre on lavapipe and llvmpipe (measured: 1).
    file["expect"] = {{{"resource", "SV_Target0"}, {"values", expected}, {"tolerance", {{"ulp", 4}}}}};
    std::string report;
    EXPECT_TRUE(run(file, RunApi::All, report)) << report;
    EXPECT_NE(report.find("vulkan: PASS SV_Target0: 32 values"), std::string::npos) << report;
    EXPECT_NE(report.find("opengl: PASS SV_Target0: 32 values"), std::string::npos) << report;
    EXPECT_NE(report.find("PASS cross-API SV_Target0"), std::string::npos) << report;
}

TEST_F(Draws, AFlippedTriangleFailsItsExpectationOnBothApis) {
    auto file = triangle();
    file["resources"]["Params"]["members"]["Tint"] = {1, -1, 1, 1}; // v negated: what a y-flip bug gives
    file["expect"] = {{{"resource", "SV_Target0"}, {"range", {0, 4}}}};
    std::string report;
    EXPECT_FALSE(run(file, RunApi::All, report));
    EXPECT_NE(report.find("vulkan: FAIL SV_Target0"), std::string::npos) << report;
    EXPECT_NE(report.find("opengl: FAIL SV_Target0"), std::string::npos) << report;
}

TEST_F(Draws, AMeshWithIndicesInstancesTwoTargetsAndADepthTest) {
    auto file = mesh();
    // Columns 0-1 are the first instance's only; from column 2 the second's nearer quad wins.
    const json ids = {1, 1, 2, 2, 2, 2, 2, 2, 1, 1, 2, 2, 2, 2, 2, 2};
    json depths = json::array();
    for (const auto& id : ids) depths.push_back(id == 1 ? 0.7 : 0.3);
    file["expect"] = {{{"resource", "SV_Target1"}, {"values", ids}},
                      // D32 holds 0.3 and 0.7 to 1 ulp of the float the vertex shader wrote.
                      {{"resource", "SV_Depth"}, {"values", depths}, {"tolerance", {{"ulp", 1}}}}};
    for (const auto api : {RunApi::Vulkan, RunApi::OpenGl}) {
        std::string report;
        EXPECT_TRUE(run(file, api, report)) << report;
    }
    file["targets"]["SV_Depth"]["test"] = "greater"; // the far quad must then win where they overlap
    std::string report;
    EXPECT_FALSE(run(file, RunApi::All, report)) << report;
    EXPECT_NE(report.find("FAIL SV_Target1"), std::string::npos) << report;
}

TEST_F(Draws, BackFacesAreCulledAsDirect3DWindsThem) {
    auto file = mesh();
    file["draw"]["instances"] = 1;
    file["vertex_input"]["POSITION"]["values"] = {-1, 1, 0.7, 1, 1, 0.7, -1, -1, 0.7, 1, -1, 0.7}; // the whole target
    file["targets"].erase("SV_Depth");
    file["expect"] = {{{"resource", "SV_Target1"}, {"range", {1, 1}}}}; // drawn everywhere it covers
    file["targets"]["SV_Target1"]["size"] = {6, 2};
    file["targets"]["SV_Target0"]["size"] = {6, 2};
    file["raster"] = {{"cull", "back"}}; // the quad is clockwise as it appears: a front face
    std::string report;
    EXPECT_TRUE(run(file, RunApi::All, report)) << report;
    file["raster"] = {{"cull", "front"}};
    EXPECT_FALSE(run(file, RunApi::All, report)) << report;
    EXPECT_NE(report.find("vulkan: FAIL"), std::string::npos);
    EXPECT_NE(report.find("opengl: FAIL"), std::string::npos);
    file["raster"] = {{"cull", "front"}, {"front", "counter_clockwise"}};
    EXPECT_TRUE(run(file, RunApi::All, report)) << report;
}

TEST_F(Draws, TheViewportCountsRowsFromTheTopAndBlendingAddsToTheClear) {
    auto file = triangle();
    file["targets"]["SV_Target0"]["clear"] = {0.25, 0.25, 0.25, 0.25};
    file["targets"]["SV_Target0"]["blend"] = "additive";
    file["viewport"] = {0, 1, 4, 1}; // the bottom row only
    file["resources"]["Params"]["members"]["Tint"] = {0, 0, 0, 1};
    // SV_Position.y is 1.5 on the bottom row; the top row keeps the clear.
    file["expect"] = {{{"resource", "SV_Target0"}, {"values", {0.25, 0.25, 0.25, 0.25, 0.25, 0.25, 0.25, 0.25,
                                                                0.25, 0.25, 0.25, 0.25, 0.25, 0.25, 0.25, 0.25,
                                                                0.25, 0.25, 0.25, 1.75, 0.25, 0.25, 0.25, 1.75,
                                                                0.25, 0.25, 0.25, 1.75, 0.25, 0.25, 0.25, 1.75}}}};
    std::string report;
    EXPECT_TRUE(run(file, RunApi::All, report)) << report;
}

// float4x4 World : WORLD is WORLD0 to WORLD3 in Direct3D's input layout: one attribute per row.
TEST_F(Draws, AMatrixInputTakesOneSemanticPerRow) {
    std::ofstream(folder / "matrix.hlsl") << R"(
struct VSIn { float2 position : POSITION; float4x4 world : WORLD; };
struct VSOut { float4 position : SV_Position; float4 row : ROW; };
VSOut VSMain(VSIn v) { VSOut o; o.position = float4(v.position, 0.5, 1); o.row = v.world[2]; return o; }
float4 PSMain(VSOut i) : SV_Target { return i.row; }
)";
    json file = json::parse(R"({
        "vertex": {"shader": "matrix.hlsl", "entry": "VSMain"}, "pixel": {"shader": "matrix.hlsl", "entry": "PSMain"},
        "vertex_input": {"POSITION": {"format": "rg32f", "values": [-1, -1, -1, 3, 3, -1]},
                         "WORLD0": {"format": "rgba32f", "values": [1, 0, 0, 0,  1, 0, 0, 0,  1, 0, 0, 0]},
                         "WORLD1": {"format": "rgba32f", "values": [0, 1, 0, 0,  0, 1, 0, 0,  0, 1, 0, 0]},
                         "WORLD2": {"format": "rgba32f", "values": [0, 0, 1, 0,  0, 0, 1, 0,  0, 0, 1, 0]},
                         "WORLD3": {"format": "rgba32f", "values": [5, 6, 7, 1,  5, 6, 7, 1,  5, 6, 7, 1]}},
        "targets": {"SV_Target0": {"format": "rgba32f", "size": [2, 2]}}})");
    // glslang reads a row per location (the compiler warns that Direct3D reads a column-major matrix's
    // columns): WORLD2 is world[2], (0, 0, 1, 0); by columns it would be (0, 0, 1, 7).
    file["expect"] = {{{"resource", "SV_Target0"}, {"fill", {0, 0, 1, 0}}}};
    std::string report;
    EXPECT_TRUE(run(file, RunApi::All, report)) << report;
    file["vertex_input"].erase("WORLD3");
    EXPECT_NE(errorOf(file).find("vertex_input: the vertex shader reads WORLD3 (float4), which vertex_input does not give"),
              std::string::npos) << errorOf(file);
}

TEST_F(Draws, BadDrawsAreOneLineNamingTheKey) {
    auto mixed = triangle();
    mixed["dispatch"] = {{"threads", {1}}};
    EXPECT_NE(errorOf(mixed).find("mixes a dispatch with a draw"), std::string::npos) << errorOf(mixed);

    auto unknownTarget = triangle();
    unknownTarget["targets"]["SV_Target3"] = {{"format", "rgba32f"}, {"size", {4, 2}}};
    EXPECT_NE(errorOf(unknownTarget).find("targets.SV_Target3: the pixel shader has no output of that semantic (it writes: SV_TARGET0 (float4))"),
              std::string::npos) << errorOf(unknownTarget);

    auto missingTarget = mesh();
    missingTarget["targets"].erase("SV_Target1");
    EXPECT_NE(errorOf(missingTarget).find("targets: the pixel shader writes SV_TARGET1 (uint), which targets does not give"),
              std::string::npos) << errorOf(missingTarget);

    auto unknownInput = mesh();
    unknownInput["vertex_input"]["NORMAL"] = {{"format", "rgb32f"}, {"values", {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}}};
    EXPECT_NE(errorOf(unknownInput).find("vertex_input.NORMAL: the vertex shader has no input of that semantic"), std::string::npos)
        << errorOf(unknownInput);

    auto missingInput = mesh();
    missingInput["vertex_input"].erase("TEXCOORD0");
    EXPECT_NE(errorOf(missingInput).find("vertex_input: the vertex shader reads TEXCOORD0 (float2), which vertex_input does not give"),
              std::string::npos) << errorOf(missingInput);

    auto wrongKind = mesh();
    wrongKind["vertex_input"]["TEXCOORD0"]["format"] = "rg32ui";
    EXPECT_NE(errorOf(wrongKind).find("vertex_input.TEXCOORD0.format: the shader reads float2, the format gives uints"), std::string::npos)
        << errorOf(wrongKind);

    auto ragged = mesh();
    ragged["vertex_input"]["TEXCOORD0"]["values"] = {0, 0, 1, 0, 0, 1};
    EXPECT_NE(errorOf(ragged).find("vertex_input.TEXCOORD0: 3 vertices, where POSITION has 4"), std::string::npos) << errorOf(ragged);

    auto outOfRange = mesh();
    outOfRange["indices"] = {0, 1, 4};
    EXPECT_NE(errorOf(outOfRange).find("indices[2]: vertex 4 of 4"), std::string::npos) << errorOf(outOfRange);

    auto badFormat = triangle();
    badFormat["targets"]["SV_Target0"]["format"] = "rgb9e5";
    EXPECT_NE(errorOf(badFormat).find("targets.SV_Target0.format: unsupported format 'rgb9e5'"), std::string::npos) << errorOf(badFormat);

    auto integerTarget = triangle();
    integerTarget["targets"]["SV_Target0"]["format"] = "r32ui";
    EXPECT_NE(errorOf(integerTarget).find("targets.SV_Target0.format: the shader writes float4, R32_UINT holds uints"),
              std::string::npos) << errorOf(integerTarget);

    auto noCount = triangle();
    noCount.erase("draw");
    EXPECT_NE(errorOf(noCount).find("draw: give \"vertices\""), std::string::npos) << errorOf(noCount);

    for (const auto& file : {mixed, unknownTarget, missingTarget, unknownInput, missingInput, wrongKind, ragged, outOfRange, badFormat,
                             integerTarget, noCount}) {
        const auto error = errorOf(file);
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
        EXPECT_EQ(error.rfind((folder / "draw.run.json").string() + ": error: ", 0), 0u) << error;
    }
}

} // namespace
} // namespace iblkit::run
