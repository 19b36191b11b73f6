#include "shading/shading_recipe.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace iblkit::shading {
namespace {

ShadingRecipe recipe(std::string name, LobeWeighting weighting, LodMapping mapping, LookupDirection direction,
                     LookupLobe lookup, bool lights, double mappingParameter = 1) {
    ShadingRecipe r;
    r.name = std::move(name);
    r.weighting = weighting;
    r.mapping = mapping;
    r.mappingParameter = mappingParameter;
    r.direction = direction;
    r.lookup = lookup;
    if (lights) r.lights = ExtractionSettings{};
    return r;
}

// Babylon.js's mip 1, α size = 2^(1 / 0.8).
constexpr double kBabylonFirstMip = 2.3784142300054421;

// The maps keep the lights where the lobe is narrower than the widest light.
ShadingRecipe handOff(ShadingRecipe recipe) {
    recipe.lobeOverLight = 1;
    return recipe;
}

// The irradiance map sums the source's mip of at most this size.
ShadingRecipe irradianceFrom(ShadingRecipe recipe, uint32_t size) {
    recipe.irradianceSource = size;
    return recipe;
}

ShadingRecipe withLights(ShadingRecipe recipe, ExtractionSettings lights) {
    recipe.lights = lights;
    return recipe;
}

ShadingRecipe glassBy(ShadingRecipe recipe, GlassShading glass) {
    recipe.glass = glass;
    return recipe;
}

std::vector<ShadingRecipe> makeBenchRecipes() {
    using enum LobeWeighting;
    using enum LodMapping;
    using D = LookupDirection;
    using L = LookupLobe;
    return {
        glassBy(recipe("kit", G1, Logarithmic, D::Fitted, L::Pair, true, kBabylonFirstMip), {GlassTransmission::Sphere, 1}),
        recipe("document", NdotL, Linear, D::Reflected, L::Roughness, false),
        recipe("quadratic", NdotL, Quadratic, D::Reflected, L::Roughness, false),
        recipe("babylon", NdotL, Babylon, D::Reflected, L::Roughness, false),
        recipe("g1", G1, Linear, D::Reflected, L::Roughness, false),
        recipe("g1-frostbite", G1, Linear, D::Frostbite, L::Roughness, false),
        recipe("g1-filament", G1, Linear, D::Filament, L::Roughness, false),
        recipe("g1-fitted", G1, Linear, D::Fitted, L::Fitted, false),
        recipe("g1-pair", G1, Linear, D::Fitted, L::Pair, false),
        recipe("lights-g1-fitted", G1, Linear, D::Fitted, L::Fitted, true),
        handOff(recipe("lights-kept-low", G1, Logarithmic, D::Fitted, L::Pair, true, kBabylonFirstMip)),
        recipe("linear-lights-pair", G1, Linear, D::Fitted, L::Pair, true),
        recipe("log-pair", G1, Logarithmic, D::Fitted, L::Pair, false, kBabylonFirstMip),
        withLights(recipe("lights-share-5", G1, Logarithmic, D::Fitted, L::Pair, true, kBabylonFirstMip), {50, 0.05, 0.1, 8}),
        withLights(recipe("lights-within-3", G1, Logarithmic, D::Fitted, L::Pair, true, kBabylonFirstMip), {50, 0.02, 0.0524, 8}),
        withLights(recipe("lights-within-10", G1, Logarithmic, D::Fitted, L::Pair, true, kBabylonFirstMip), {50, 0.02, 0.1745, 8}),
        withLights(recipe("lights-above-20", G1, Logarithmic, D::Fitted, L::Pair, true, kBabylonFirstMip), {20, 0.02, 0.1, 8}),
        irradianceFrom(recipe("irradiance-64", G1, Logarithmic, D::Fitted, L::Pair, true, kBabylonFirstMip), 64),
        glassBy(recipe("glass-tabulated", G1, Logarithmic, D::Fitted, L::Pair, true, kBabylonFirstMip),
                {GlassTransmission::Tabulated, 1}),
        glassBy(recipe("glass-tabulated-0.5", G1, Logarithmic, D::Fitted, L::Pair, true, kBabylonFirstMip),
                {GlassTransmission::Tabulated, 0.5}),
        glassBy(recipe("glass-schlick", G1, Logarithmic, D::Fitted, L::Pair, true, kBabylonFirstMip), {GlassTransmission::Schlick, 1}),
        // What three.js r187 and Filament read (runtime/profiles/): lod = r (2 - r) n, lerp(R, N, α²),
        // one lookup, the lights as the engine's own.
        recipe("quadratic-lights", G1, Quadratic, D::Filament, L::Roughness, true),
        // What Babylon.js 9 reads: lod = 0.8 log2(α size), R, one lookup.
        recipe("babylon-lights", G1, Babylon, D::Reflected, L::Roughness, true),
        // What the glTF Sample Viewer reads: lod = r (mips - 1), R, one lookup.
        recipe("linear-lights", G1, Linear, D::Reflected, L::Roughness, true),
    };
}

} // namespace

std::string_view nameOf(LookupDirection direction) {
    switch (direction) {
    case LookupDirection::Reflected: return "reflected";
    case LookupDirection::Frostbite: return "frostbite";
    case LookupDirection::Filament: return "filament";
    case LookupDirection::Fitted: return "fitted";
    }
    return "reflected";
}

std::string_view nameOf(GlassTransmission transmission) {
    switch (transmission) {
    case GlassTransmission::Schlick: return "Schlick";
    case GlassTransmission::Tabulated: return "tabulated";
    case GlassTransmission::Sphere: return "sphere";
    }
    return "Schlick";
}

std::string_view nameOf(LookupLobe lookup) {
    switch (lookup) {
    case LookupLobe::Roughness: return "roughness";
    case LookupLobe::Fitted: return "fitted";
    case LookupLobe::Pair: return "pair";
    }
    return "roughness";
}

const std::vector<ShadingRecipe>& benchRecipes() {
    static const auto recipes = makeBenchRecipes();
    return recipes;
}

const ShadingRecipe& defaultRecipe() { return benchRecipes()[0]; }
const ShadingRecipe& documentRecipe() { return benchRecipes()[1]; }

const ShadingRecipe& recipeNamed(std::string_view name) {
    std::string names;
    for (const auto& recipe : benchRecipes()) {
        if (recipe.name == name) return recipe;
        names += (names.empty() ? "" : ", ") + recipe.name;
    }
    throw std::invalid_argument("no shading recipe '" + std::string(name) + "': " + names);
}

MipSchedule scheduleOf(const ShadingRecipe& recipe, uint32_t mips, uint32_t size) {
    return {recipe.mapping, recipe.mappingParameter, mips, size};
}

uint32_t lightLevelOf(const ShadingRecipe& recipe, const MipSchedule& schedule, const std::vector<EnvironmentLight>& lights) {
    if (lights.empty() || recipe.lobeOverLight <= 0) return 0;
    double widest = 0;
    for (const auto& light : lights) widest = std::max(widest, light.angularRadius);
    for (uint32_t mip = 1; mip < schedule.mips; ++mip) {
        const double roughness = schedule.roughnessOf(mip);
        if (roughness * roughness >= recipe.lobeOverLight * widest) return mip;
    }
    return schedule.mips;
}

} // namespace iblkit::shading
