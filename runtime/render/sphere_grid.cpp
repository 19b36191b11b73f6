#include "render/sphere_grid.hpp"

#include <fmt/core.h>

namespace iblkit::render {

const SphereGrid& defaultSphereGrid() {
    static const SphereGrid grid{
        {0.02f, 0.05f, 0.1f, 0.15f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f, 0.9f, 1.f},
        {{"plastic", kGold, 0.f, 0.f},
         {"half-metal", kGold, 0.5f, 0.f},
         {"gold", kGold, 1.f, 0.f},
         {"silver", kSilver, 1.f, 0.f},
         {"glass", glm::vec3(1.f), 0.f, 1.f, 1.5f}}};
    return grid;
}

std::string roughnessTableHead(const SphereGrid& grid, const std::string& corner) {
    std::string head = "| " + corner + " |", rule = "|---|";
    for (const float roughness : grid.roughness) {
        head += fmt::format(" r {:g} |", roughness);
        rule += "---:|";
    }
    return head + "\n" + rule + "\n";
}

std::vector<float> packSpheres(const SphereGrid& grid) {
    std::vector<float> values;
    for (const auto& row : grid.rows)
        for (const float roughness : grid.roughness)
            values.insert(values.end(), {row.albedo.r, row.albedo.g, row.albedo.b, roughness, row.metalness,
                                         row.transmittance, row.eta, 0.f});
    return values;
}

} // namespace iblkit::render
