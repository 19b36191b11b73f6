// Lights files as users write them, and every way the renderer refuses one: in one line that names
// the light and the field.
#include "render/lights_file.hpp"
#include "render/render_error.hpp"

#include <gtest/gtest.h>

namespace iblkit::render {
namespace {

TEST(LightsFile, ReadsEachKindOfLight) {
    const auto lights = parseLights(R"({"lights": [
        {"type": "directional", "direction": [0, 0, -2], "radiance": [3, 2, 1]},
        {"type": "point", "position": [2, 3, 4], "intensity": [5, 5, 5]},
        {"type": "area", "corner": [-1, -1, 3], "edge_u": [2, 0, 0], "edge_v": [0, 2, 0], "radiance": [1, 1, 1]}]})",
                                    "lights.json");
    ASSERT_EQ(lights.size(), 3u);
    EXPECT_EQ(lights[0].kind, RenderLight::Kind::Directional);
    EXPECT_FLOAT_EQ(lights[0].a.z, -1.f) << "directions are normalized";
    EXPECT_EQ(lights[1].kind, RenderLight::Kind::Point);
    EXPECT_FLOAT_EQ(lights[1].a.y, 3.f);
    EXPECT_EQ(lights[2].kind, RenderLight::Kind::Area);
    EXPECT_FLOAT_EQ(lights[2].c.y, 2.f);
}

TEST(LightsFile, PacksFourFloat4PerLightAsTheShaderReadsThem) {
    const std::vector<RenderLight> lights = {
        {RenderLight::Kind::Point, {2, 3, 4}, {}, {}, {5, 6, 7}},
        {RenderLight::Kind::Area, {-1, -1, 3}, {2, 0, 0}, {0, 2, 0}, {8, 9, 10}}};
    const auto packed = packLights(lights);
    ASSERT_EQ(packed.size(), 32u);
    EXPECT_EQ(packed[0], 1.f) << "type 1: point";
    EXPECT_EQ(packed[4], 2.f) << "its position";
    EXPECT_EQ(packed[8], 5.f) << "its intensity";
    EXPECT_EQ(packed[16], 2.f) << "type 2: area";
    EXPECT_EQ(packed[17], 8.f) << "an area light's radiance rides in its first float4";
    EXPECT_EQ(packed[24], 2.f) << "its first edge";
    EXPECT_EQ(packed[29], 2.f) << "its second edge";
    EXPECT_EQ(packLights({}).size(), 4u) << "a buffer cannot be empty";
}

void expectRefused(const std::string& text, const std::string& expected) {
    try {
        parseLights(text, "lights.json");
        ADD_FAILURE() << "accepted: " << text;
    } catch (const RenderError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(expected), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_EQ(message.rfind("lights.json", 0), 0u) << message;
    }
}

TEST(LightsFile, RefusesWhatTheRendererCannotDraw) {
    expectRefused("{\"lights\": [", "not valid JSON");
    expectRefused("[]", "expected an object with a \"lights\" array");
    expectRefused(R"({"lights": [], "sun": 1})", "unknown field \"sun\"");
    expectRefused(R"({"lights": [{"type": "spot"}]})", "light 0: unknown type \"spot\"");
    expectRefused(R"({"lights": [{"direction": [0, 0, 1]}]})", "with a \"type\"");
    expectRefused(R"({"lights": [{"type": "directional", "radiance": [1, 1, 1]}]})", "\"direction\" is missing");
    expectRefused(R"({"lights": [{"type": "directional", "direction": [0, 0], "radiance": [1, 1, 1]}]})",
                  "\"direction\" must be an array of 3 numbers");
    expectRefused(R"({"lights": [{"type": "directional", "direction": [0, 0, 0], "radiance": [1, 1, 1]}]})",
                  "\"direction\" is zero");
    expectRefused(R"({"lights": [{"type": "directional", "direction": [0, 0, 1], "radiance": [1, -1, 1]}]})",
                  "\"radiance\" is negative");
    expectRefused(R"({"lights": [{"type": "directional", "direction": [0, 0, 1], "radiance": [1, 1e39, 1]}]})",
                  "\"radiance\" holds 1e+39, past the 1e+15 it may be");
    // 3e38 is a finite float, and was called "not a finite float"; 1e21 passed, and the reference's
    // sums of squares overflowed ("standard error is inf %, raise --samples").
    expectRefused(R"({"lights": [{"type": "directional", "direction": [0, 0, 1], "radiance": [3e38, 1, 1]}]})",
                  "\"radiance\" holds 3e+38, past the 1e+15 it may be");
    expectRefused(R"({"lights": [{"type": "directional", "direction": [0, 0, 1], "radiance": [1e21, 1e21, 1e21]}]})",
                  "\"radiance\" holds 1e+21, past the 1e+15 it may be");
    expectRefused(R"({"lights": [{"type": "directional", "direction": [0, 0, 1e31], "radiance": [1, 1, 1]}]})",
                  "\"direction\" holds 1e+31, past the 1e+30 it may be");
    expectRefused(R"({"lights": [{"type": "directional", "direction": [0, 0, 1], "radiance": [1, 1, 1], "size": 2}]})",
                  "unknown field \"size\"");
    expectRefused(R"({"lights": [{"type": "point", "position": [0.5, 0, 0], "intensity": [1, 1, 1]}]})",
                  "\"position\" is 0.5 from the centre of the sphere (radius 1 about the origin): a point light must be "
                  "at least 1.001 away, outside it");
    // Outside the sphere, but within the clearance: once called "inside".
    expectRefused(R"({"lights": [{"type": "point", "position": [0, 0, 1.0005], "intensity": [1, 1, 1]}]})",
                  "\"position\" is 1.0005 from the centre");
    expectRefused(R"({"lights": [{"type": "area", "corner": [0, 0, 3], "edge_u": [1, 0, 0], "edge_v": [2, 0, 0],
                  "radiance": [1, 1, 1]}]})",
                  "parallel");
    expectRefused(R"({"lights": [{"type": "area", "corner": [-2, -2, 0.5], "edge_u": [4, 0, 0], "edge_v": [0, 4, 0],
                  "radiance": [1, 1, 1]}]})",
                  "its plane is 0.5 from the centre of the sphere (radius 1 about the origin), so it cuts the sphere");
}

TEST(LightsFile, AMissingFileIsOneLine) {
    try {
        readLightsFile("/nonexistent/lights.json");
        ADD_FAILURE() << "a missing file was read";
    } catch (const RenderError& error) {
        EXPECT_NE(std::string(error.what()).find("does not exist"), std::string::npos) << error.what();
    }
}

} // namespace
} // namespace iblkit::render
