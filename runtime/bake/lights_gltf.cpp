#include "lights_gltf.hpp"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace iblkit::bake {
namespace {

using nlohmann::json;

// The unit quaternion (x, y, z, w) that turns +Z into `direction`, so that -Z turns into the
// direction the light travels.
json rotationOntoDirection(const glm::dvec3& direction) {
    const glm::dvec3 z(0, 0, 1), d = glm::normalize(direction);
    const double cosine = glm::dot(z, d);
    if (cosine < -1 + 1e-12) return {1.0, 0.0, 0.0, 0.0}; // half a turn about X
    const glm::dvec3 axis = glm::cross(z, d);
    const double w = 1 + cosine, norm = std::sqrt(w * w + glm::dot(axis, axis));
    return {axis.x / norm, axis.y / norm, axis.z / norm, w / norm};
}

json lightJson(const shading::EnvironmentLight& light, size_t index) {
    const glm::dvec3 illuminance = light.radiance * light.solidAngle;
    const double intensity = std::max({illuminance.r, illuminance.g, illuminance.b});
    const glm::dvec3 color = intensity > 0 ? illuminance / intensity : glm::dvec3(1);
    return {{"type", "directional"},
            {"name", "environment light " + std::to_string(index)},
            {"color", {color.r, color.g, color.b}},
            {"intensity", intensity},
            {"extras", {{"radiance", {light.radiance.r, light.radiance.g, light.radiance.b}},
                        {"angular_radius", light.angularRadius},
                        {"solid_angle", light.solidAngle},
                        {"share_of_the_light", light.share},
                        {"direction", {light.direction.x, light.direction.y, light.direction.z}}}}};
}

} // namespace

std::string lightsGltf(const std::vector<shading::EnvironmentLight>& lights, const std::string& generator) {
    json lightList = json::array(), nodes = json::array(), nodeIndices = json::array();
    for (size_t i = 0; i < lights.size(); ++i) {
        lightList.push_back(lightJson(lights[i], i));
        nodes.push_back({{"name", "environment light " + std::to_string(i)},
                         {"rotation", rotationOntoDirection(lights[i].direction)},
                         {"extensions", {{"KHR_lights_punctual", {{"light", i}}}}}});
        nodeIndices.push_back(i);
    }
    const json gltf = {{"asset", {{"version", "2.0"}, {"generator", generator}}},
                       {"extensionsUsed", {"KHR_lights_punctual"}},
                       {"extensions", {{"KHR_lights_punctual", {{"lights", lightList}}}}},
                       {"scene", 0},
                       {"scenes", {{{"name", "environment lights"}, {"nodes", nodeIndices}}}},
                       {"nodes", nodes}};
    return gltf.dump(2) + "\n";
}

} // namespace iblkit::bake
