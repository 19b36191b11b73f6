#pragma once

#include <glm/vec3.hpp>

#include <filesystem>
#include <string_view>
#include <vector>

namespace iblkit::render {

// The document's lights (hlsl/document/Common/Lights.fxh), in the frame of every sphere: each
// sphere has radius 1 and sits at the origin; +Z points at the camera.
struct RenderLight {
    enum class Kind { Directional, Point, Area };
    Kind kind;
    glm::vec3 a{0.f};        // directional: the direction the light travels; point: its position; area: a corner
    glm::vec3 b{0.f};        // area: the first edge
    glm::vec3 c{0.f};        // area: the second edge (it emits on the side of cross(b, c))
    glm::vec3 radiance{0.f}; // directional and area: radiance; point: intensity
};

inline constexpr size_t kMaxLights = 64;

// A lights file: {"lights": [{"type": "directional", "direction": [x, y, z], "radiance": [r, g, b]},
// {"type": "point", "position": [...], "intensity": [...]}, {"type": "area", "corner": [...],
// "edge_u": [...], "edge_v": [...], "radiance": [...]}]}. Refused, in one line naming the light and
// the field: an unknown type or field, a number that is not finite, a coordinate past 1e30 or a
// radiance or intensity past 1e15, negative radiance, a zero direction or edge, parallel edges, a
// point light within 1.001 of the sphere's centre or an area light whose plane is (it would cut
// the sphere, which would hide part of it from itself: the renderer does not model that).
// Throws RenderError.
std::vector<RenderLight> parseLights(std::string_view text, std::string_view name);
std::vector<RenderLight> readLightsFile(const std::filesystem::path& path);

// Four float4 per light, as RenderReferenceCS reads them.
std::vector<float> packLights(const std::vector<RenderLight>& lights);

} // namespace iblkit::render
