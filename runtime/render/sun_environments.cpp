#include "render/sun_environments.hpp"

#include "bake_settings.hpp"
#include "reference/sky_environment.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace iblkit::render {
namespace {

using glm::dvec3;

std::optional<dvec3> sunDirection(std::string_view name) {
    if (name == "sun-front") return glm::normalize(dvec3(0.35, 0.45, 0.82));
    if (name == "sun-side") return glm::normalize(dvec3(0.94, 0.34, 0.0));
    if (name == "sun-behind") return glm::normalize(dvec3(0.25, 0.3, -0.92));
    return std::nullopt;
}

dvec3 background(dvec3 d) {
    return d.y >= 0 ? reference::SkyRadiance(d) : reference::GroundRadiance(d);
}

} // namespace

std::optional<bake::EnvironmentInput> sunEnvironment(std::string_view name) {
    const auto sun = sunDirection(name);
    if (!sun) return std::nullopt;
    const uint32_t size = bake::kDefaultSize, supersample = 8;
    const double radius = kSunRadiusDegrees * std::numbers::pi / 180, texel = 2.0 / size;
    bake::EnvironmentInput input;
    input.kind = bake::InputKind::Cube;
    input.cubeSize = size;
    input.cubeTexels.resize(size_t(6) * size * size * 4);
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x) {
                const dvec3 centre = reference::CubeFaceDirection<double>(face, glm::dvec2((x + 0.5) / size, (y + 0.5) / size));
                dvec3 radiance = background(centre);
                if (std::acos(std::clamp(glm::dot(centre, *sun), -1.0, 1.0)) < radius + 2 * texel) {
                    double covered = 0;
                    for (uint32_t j = 0; j < supersample; ++j)
                        for (uint32_t i = 0; i < supersample; ++i) {
                            const glm::dvec2 uv((x + (i + 0.5) / supersample) / size, (y + (j + 0.5) / supersample) / size);
                            const dvec3 d = reference::CubeFaceDirection<double>(face, uv);
                            covered += std::acos(std::clamp(glm::dot(d, *sun), -1.0, 1.0)) < radius ? 1 : 0;
                        }
                    radiance += dvec3(1.0, 0.95, 0.9) * kSunRadiance * covered / double(supersample * supersample);
                }
                float* out = &input.cubeTexels[((size_t(face) * size + y) * size + x) * 4];
                out[0] = float(radiance.r), out[1] = float(radiance.g), out[2] = float(radiance.b), out[3] = 1.f;
            }
    return input;
}

} // namespace iblkit::render
