#include "lights_file.hpp"

#include "render_error.hpp"

#include "files.hpp"
#include "image_error.hpp"

#include <fmt/core.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <set>

namespace iblkit::render {
namespace {

using Json = nlohmann::json;

struct LightContext {
    std::string_view file;
    size_t index;
    [[noreturn]] void fail(const std::string& what) const {
        throw RenderError(fmt::format("{}: light {}: {}", file, index, what));
    }
};

// A position, direction or edge: past this the renderer's float geometry has no precision left.
constexpr double kMaxCoordinate = 1e30;
// A radiance or intensity: the reference sums the squares of its samples in floats (for the
// standard error), and past this a bright path's square overflows them.
constexpr double kMaxRadiance = 1e15;
// How far from the sphere's centre a point light, or an area light's plane, must be.
constexpr float kClearance = 1.001f;
// 64 lights take a few kilobytes; a file of more is not a lights file.
constexpr uint64_t kMaxLightsFileBytes = 1 << 20;

glm::vec3 vectorField(const Json& light, const char* field, double limit, const LightContext& where) {
    if (!light.contains(field)) where.fail(fmt::format("\"{}\" is missing", field));
    const auto& value = light[field];
    if (!value.is_array() || value.size() != 3) where.fail(fmt::format("\"{}\" must be an array of 3 numbers", field));
    glm::vec3 vector;
    for (int i = 0; i < 3; ++i) {
        if (!value[i].is_number()) where.fail(fmt::format("\"{}\" must be an array of 3 numbers", field));
        const double number = value[i].get<double>();
        if (!std::isfinite(number)) where.fail(fmt::format("\"{}\" holds {}, which is not a finite number", field, number));
        if (std::abs(number) > limit) where.fail(fmt::format("\"{}\" holds {:g}, past the {:g} it may be", field, number, limit));
        vector[i] = float(number);
    }
    return vector;
}

glm::vec3 vectorField(const Json& light, const char* field, const LightContext& where) {
    return vectorField(light, field, kMaxCoordinate, where);
}

glm::vec3 radianceField(const Json& light, const char* field, const LightContext& where) {
    const auto radiance = vectorField(light, field, kMaxRadiance, where);
    if (radiance.x < 0 || radiance.y < 0 || radiance.z < 0) where.fail(fmt::format("\"{}\" is negative", field));
    return radiance;
}

void requireOnlyFields(const Json& light, const std::set<std::string>& fields, const LightContext& where) {
    for (const auto& [key, value] : light.items())
        if (key != "type" && !fields.count(key)) where.fail(fmt::format("unknown field \"{}\"", key));
}

RenderLight directional(const Json& light, const LightContext& where) {
    requireOnlyFields(light, {"direction", "radiance"}, where);
    const auto direction = vectorField(light, "direction", where);
    if (glm::length(direction) < 1e-6f) where.fail("\"direction\" is zero");
    return {RenderLight::Kind::Directional, glm::normalize(direction), {}, {}, radianceField(light, "radiance", where)};
}

RenderLight point(const Json& light, const LightContext& where) {
    requireOnlyFields(light, {"position", "intensity"}, where);
    const auto position = vectorField(light, "position", where);
    if (const float distance = glm::length(position); distance <= kClearance)
        where.fail(fmt::format("\"position\" is {:g} from the centre of the sphere (radius 1 about the origin): a point "
                               "light must be at least {:g} away, outside it",
                               distance, kClearance));
    return {RenderLight::Kind::Point, position, {}, {}, radianceField(light, "intensity", where)};
}

RenderLight area(const Json& light, const LightContext& where) {
    requireOnlyFields(light, {"corner", "edge_u", "edge_v", "radiance"}, where);
    const auto corner = vectorField(light, "corner", where);
    const auto edgeU = vectorField(light, "edge_u", where), edgeV = vectorField(light, "edge_v", where);
    const auto across = glm::cross(edgeU, edgeV);
    if (glm::length(across) < 1e-6f * std::max(1.f, glm::length(edgeU) * glm::length(edgeV)))
        where.fail("\"edge_u\" and \"edge_v\" are zero or parallel");
    if (const float distance = std::abs(glm::dot(glm::normalize(across), corner)); distance <= kClearance)
        where.fail(fmt::format("its plane is {:g} from the centre of the sphere (radius 1 about the origin), so it cuts the "
                               "sphere or grazes it: it must be at least {:g} away (the renderer has the sphere hide only "
                               "whole lights)",
                               distance, kClearance));
    return {RenderLight::Kind::Area, corner, edgeU, edgeV, radianceField(light, "radiance", where)};
}

RenderLight parseLight(const Json& light, const LightContext& where) {
    if (!light.is_object() || !light.contains("type") || !light["type"].is_string())
        where.fail("each light must be an object with a \"type\"");
    const auto type = light["type"].get<std::string>();
    if (type == "directional") return directional(light, where);
    if (type == "point") return point(light, where);
    if (type == "area") return area(light, where);
    where.fail(fmt::format("unknown type \"{}\" (directional, point or area)", type));
}

} // namespace

std::vector<RenderLight> parseLights(std::string_view text, std::string_view name) {
    const auto json = Json::parse(text, nullptr, false);
    if (json.is_discarded()) throw RenderError(fmt::format("{}: not valid JSON", name));
    if (!json.is_object() || !json.contains("lights") || !json["lights"].is_array())
        throw RenderError(fmt::format("{}: expected an object with a \"lights\" array", name));
    for (const auto& [key, value] : json.items())
        if (key != "lights") throw RenderError(fmt::format("{}: unknown field \"{}\"", name, key));
    const auto& list = json["lights"];
    if (list.size() > kMaxLights)
        throw RenderError(fmt::format("{}: {} lights, more than the {} the renderer takes", name, list.size(), kMaxLights));
    std::vector<RenderLight> lights;
    for (size_t i = 0; i < list.size(); ++i) lights.push_back(parseLight(list[i], {name, i}));
    return lights;
}

std::vector<RenderLight> readLightsFile(const std::filesystem::path& path) {
    std::error_code error;
    if (!std::filesystem::exists(path, error))
        throw RenderError(fmt::format("lights file {} does not exist", path.string()));
    try {
        // The environment's and the scene's reader: a regular file (never a pipe to wait on), bounded.
        const auto bytes = image_io::readFileBytes(path, kMaxLightsFileBytes);
        return parseLights(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path.string());
    } catch (const image_io::ImageError& refused) {
        throw RenderError(fmt::format("lights file {}", refused.what()));
    }
}

std::vector<float> packLights(const std::vector<RenderLight>& lights) {
    std::vector<float> packed;
    for (const auto& light : lights) {
        const bool isArea = light.kind == RenderLight::Kind::Area;
        const glm::vec3 head = isArea ? light.radiance : glm::vec3(0.f);
        const glm::vec3 second = isArea ? light.b : light.radiance;
        packed.insert(packed.end(), {float(int(light.kind)), head.x, head.y, head.z});
        packed.insert(packed.end(), {light.a.x, light.a.y, light.a.z, 0.f});
        packed.insert(packed.end(), {second.x, second.y, second.z, 0.f});
        packed.insert(packed.end(), {light.c.x, light.c.y, light.c.z, 0.f});
    }
    if (packed.empty()) packed.assign(4, 0.f); // a buffer cannot be empty; LightCount is 0
    return packed;
}

} // namespace iblkit::render
