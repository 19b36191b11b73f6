#pragma once

#include "bake_settings.hpp"
#include "bench_curves.hpp"
#include "scene_materials.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::bake {

// A step's expected cost and error, from the bench's measured curves at the method and count
// the bake uses, scaled from the bench's sizes to the bake's by texel count; empty where the
// bench did not measure that method and count.
struct Estimate {
    std::optional<double> deviceMs;
    std::optional<double> errorRms, errorMax; // worst over the bench's environments
};

struct SpecularMipPlan {
    uint32_t mip = 0;
    float roughness = 0;
    uint32_t faceSize = 0;
    bool needed = false; // its roughness bracket meets the roughness the scene uses
    Estimate estimate;
};

// What a bake computes for a scene (or for everything, without one): the outputs, the specular
// mips, the LUT rows, the kernels, and what each step should cost.
struct BakePlan {
    std::optional<std::filesystem::path> scene;
    scene::ValueRange roughness;          // every lit material's, clearcoats included
    bool specular = true, irradiance = true, lut = true;
    const shading::ShadingRecipe* recipe = nullptr; // how the maps are made and read; its lights, when it takes them out
    shading::MipSchedule schedule;                  // the recipe's, for the bake's chain: each mip's roughness and lod
    std::vector<SpecularMipPlan> mips;
    uint32_t lutFirstRow = 0, lutLastRow = 0; // the rows bilinear reads of `roughness` touch
    std::vector<std::string> kernels;     // shader names, with the defines that make their permutation
    Estimate specularEstimate, lutEstimate, irradianceEstimate;
    std::vector<std::string> reasons;     // why each output is or is not needed, in words
    std::vector<std::string> unknownExtensions;
    std::vector<std::string> notes;       // what the scene reader assumed

    std::vector<bool> prefilteredMips() const; // by mip: whether it is prefiltered (needed) or filled
};

// Which outputs the scene's materials need (all of them without a scene): what planBake says,
// known before the cube's size is.
struct NeededOutputs {
    bool specular = true, irradiance = true, lut = true;
};
NeededOutputs neededOutputs(const std::optional<scene::SceneMaterials>& scene);

// The plan for `settings` (at their face size and chain), for `scene` when one is given. A specular
// mip sits at the roughness the recipe's schedule gives it (m / (M - 1) for the documents'), and
// a renderer reads it for every roughness between its neighbours' (trilinear filtering between
// mips): it is needed when that bracket meets the used range. The bench measured the documents'
// N·L lobe: a recipe of another lobe has no error estimate. Irradiance is needed for any lit material that is not all metal; the specular
// chain and the LUT for any lit material; transmission (KHR_materials_transmission, _volume)
// needs the whole chain, since refraction blurs by thickness as well as roughness.
BakePlan planBake(const ResolvedSettings& settings, const std::optional<scene::SceneMaterials>& scene,
                  const BenchCurves& curves = BenchCurves::builtIn());

nlohmann::json planJson(const BakePlan& plan);
std::string planText(const BakePlan& plan);

} // namespace iblkit::bake
