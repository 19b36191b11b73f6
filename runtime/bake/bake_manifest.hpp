#pragma once

#include "bake_outputs.hpp"
#include "bake_plan.hpp"
#include "bake_settings.hpp"
#include "environment_input.hpp"
#include "gpu_steps.hpp"

#include <nlohmann/json.hpp>

namespace iblkit::bake {

struct ManifestFacts {
    std::string toolVersion;
    std::string device;
    const EnvironmentInput* input;
    const ResolvedSettings* settings;
    uint32_t size;
    uint32_t mips;
    const IrradianceSh* irradiance;
    const std::vector<HalfRangeClamp>* halfRangeClamps;
    float previewExposure;
    const BakePlan* plan; // what was computed: every output and mip, without a scene
    const std::vector<shading::EnvironmentLight>* lights; // those the recipe took out
    uint32_t lightLevel;
    bool lobeTableFile; // lobe_table.ktx2 is written
};

// manifest.json without its "files" list (added once every file is written).
nlohmann::json bakeManifest(const ManifestFacts& facts);
nlohmann::json filesJson(const std::vector<WrittenFile>& files);
// How the maps are made and read: the recipe, each mip's roughness, the lod mapping, the lobe,
// the lookups, the lights; the manifest's "shading" and the specular KTX2's "iblkit.shading".
nlohmann::json shadingJson(const ManifestFacts& facts);
// Whether the recipe's shading reads the lobe table (its fitted direction or lookups).
bool readsLobeTable(const shading::ShadingRecipe& recipe);
size_t clampedValueCount(const std::vector<HalfRangeClamp>& clamps);
// Per clamped texture: its name, the values clamped and the worst mip's share of energy lost.
nlohmann::json halfRangeClampsJson(const std::vector<HalfRangeClamp>& clamps);
// Nine RGB coefficients as [[r, g, b], ...].
nlohmann::json coefficientsJson(const std::array<glm::dvec3, 9>& coefficients);

// Irradiance coefficients from radiance ones: E(n) / pi = sum c_lm Y_lm(n) with c_lm = A_l / pi
// L_lm and A = (pi, 2 pi / 3, pi / 4) per band (Ramamoorthi and Hanrahan 2001).
std::array<glm::dvec3, 9> irradianceCoefficients(const std::array<glm::dvec3, 9>& radiance);

} // namespace iblkit::bake
