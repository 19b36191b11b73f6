#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::render {

// A row of the grid: one material at every roughness of the columns.
struct SphereRow {
    std::string name;   // "gold", "glass", ...: how tables and errors.json name the row
    glm::vec3 albedo{1.f};
    float metalness = 0, transmittance = 0, eta = 1.5f;
    bool glass() const { return transmittance > 0; }
};

// The spheres of hlsl/Common/SphereGrid.fxh: one column per roughness, one row per material.
struct SphereGrid {
    std::vector<float> roughness;
    std::vector<SphereRow> rows;
    uint32_t columns() const { return uint32_t(roughness.size()); }
    uint32_t rowCount() const { return uint32_t(rows.size()); }
};

// Gold's reflectance at normal incidence, as in the preview: orange plastic at metalness 0.
inline constexpr glm::vec3 kGold{1.f, 0.766f, 0.336f};
// Silver's (Naty Hoffman's table of F0 for metals in linear sRGB).
inline constexpr glm::vec3 kSilver{0.972f, 0.960f, 0.915f};

// The render's grid: roughness 0.02, 0.05, 0.1, 0.15, 0.2 where the lobe changes fastest, then
// 0.3 to 1 by tenths; rows of plastic (gold's colour at metalness 0), half-metal, gold, silver
// and glass (eta 1.5, white). GGX of roughness 0 is a delta the ported BSDF cannot evaluate (D is
// 0/0 at N·H = 1): the first column is a mirror to the eye instead.
const SphereGrid& defaultSphereGrid();

// Two float4 per cell, row after row, as SphereGrid.fxh reads them.
std::vector<float> packSpheres(const SphereGrid& grid);

// The head of a Markdown table with one column per roughness ("| corner | r 0.02 | ... |" and its
// rule, the roughness columns aligned right).
std::string roughnessTableHead(const SphereGrid& grid, const std::string& corner);

} // namespace iblkit::render
