#pragma once

#include "shading/light_extraction.hpp"
#include "shading/lobe_table.hpp"
#include "shading/mip_schedule.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace iblkit::shading {

// Where the specular lookup looks (hlsl/Common/ImageBasedLighting.fxh's IBL_DIRECTION_*).
enum class LookupDirection : uint32_t { Reflected = 0, Frostbite = 1, Filament = 2, Fitted = 3 };
// What it reads: one lookup at the surface's roughness, one at the lobe table's, or the table's pair.
enum class LookupLobe : uint32_t { Roughness = 0, Fitted = 1, Pair = 2 };

std::string_view nameOf(LookupDirection direction);
std::string_view nameOf(LookupLobe lookup);

// How glass reads the maps (hlsl/Common/ImageBasedLighting.fxh's IBL_GLASS_*, IblGlassReadOf):
// along the smooth sphere's refraction, at the surface's roughness times roughnessScale, passing
// Schlick's 1 - F at each crossing or the transmission table's share of the rough interface
// (shading/transmission_table.hpp); or as the sphere transmission table's fit of the rough
// sphere's exiting light (shading/sphere_transmission.hpp), where roughnessScale plays no part.
enum class GlassTransmission : uint32_t { Schlick = 0, Tabulated = 1, Sphere = 2 };
std::string_view nameOf(GlassTransmission transmission);
struct GlassShading {
    GlassTransmission transmission = GlassTransmission::Schlick;
    double roughnessScale = 1;
};

// How the maps are made and read: one record, written by the bake into its manifest and read by
// the shading (docs/shading.md measures each against the Monte Carlo reference).
struct ShadingRecipe {
    std::string name;
    LobeWeighting weighting = LobeWeighting::NdotL;
    LodMapping mapping = LodMapping::Linear;
    double mappingParameter = 1; // LodMapping::Power's p, Logarithmic's c
    LookupDirection direction = LookupDirection::Reflected;
    LookupLobe lookup = LookupLobe::Roughness;
    // Bright sources taken out as lights; none keeps them in the maps.
    std::optional<ExtractionSettings> lights;
    // The maps keep the lights below the first mip whose lobe, α = r², is this many times as wide
    // as the widest light's angular radius, where the prefiltered texels hold the light's true
    // shape; 0: no mip keeps them, and the shading adds them at every roughness.
    double lobeOverLight = 0;
    // The irradiance cube sums the source's first mip of at most this size.
    uint32_t irradianceSource = 32;
    GlassShading glass;
};

// The documents' recipe: N·L lobe, linear lods, R, one lookup at the surface's roughness, no lights.
const ShadingRecipe& documentRecipe();
// The kit's default, chosen by the shading bench (docs/shading.md).
const ShadingRecipe& defaultRecipe();
// Every recipe the shading bench measures, by name; the first two are the default and the documents'.
const std::vector<ShadingRecipe>& benchRecipes();
// Throws std::invalid_argument listing the names.
const ShadingRecipe& recipeNamed(std::string_view name);

// The mip schedule of a recipe for a chain of `mips` levels from a `size` face.
MipSchedule scheduleOf(const ShadingRecipe& recipe, uint32_t mips, uint32_t size);

// The first mip prefiltered without the lights: mips below it keep them (recipe.lobeOverLight);
// `mips` when no mip is wide enough, 0 when there are no lights.
uint32_t lightLevelOf(const ShadingRecipe& recipe, const MipSchedule& schedule, const std::vector<EnvironmentLight>& lights);

} // namespace iblkit::shading
