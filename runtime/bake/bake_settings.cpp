#include "bake_settings.hpp"

#include "bake_error.hpp"

#include "kernels/specular_method.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <string>

namespace iblkit::bake {
namespace {

void requireRange(const char* name, uint32_t value, uint32_t low, uint32_t high) {
    if (value < low || value > high)
        throw BakeError(std::string(name) + " " + std::to_string(value) + " is out of range (" + std::to_string(low) +
                        " to " + std::to_string(high) + ")");
}

void requirePowerOfTwo(const char* name, uint32_t value) {
    if (!std::has_single_bit(value))
        throw BakeError(std::string(name) + " " + std::to_string(value) +
                        " is not a power of two (each mip must halve the one above it exactly)");
}

void requireSpecularMethod(const std::string& method) {
    const auto all = kernels::specularMethods();
    if (std::find(all.begin(), all.end(), method) == all.end())
        throw BakeError(fmt::format("--method {} is not a prefilter method (there are: {})", method, fmt::join(all, ", ")));
}

void requireLutMethod(const std::string& method) {
    const auto all = kernels::lutMethods();
    if (std::find(all.begin(), all.end(), method) == all.end())
        throw BakeError(fmt::format("--lut-method {} is not a LUT method (there are: {})", method, fmt::join(all, ", ")));
}

const profiles::EngineProfile& profileOf(const BakeSettings& settings) {
    try {
        return profiles::profileNamed(settings.profile);
    } catch (const std::invalid_argument& error) {
        throw BakeError(fmt::format("--profile: {}", error.what()));
    }
}

const shading::ShadingRecipe& recipeOf(const BakeSettings& settings) {
    if (settings.recipe) return shading::recipeNamed(*settings.recipe);
    if (const auto& profile = profileOf(settings); profile.name != profiles::defaultProfile().name)
        return shading::recipeNamed(profile.recipe);
    return kernels::specularKindOf(settings.specularMethod) == kernels::SpecularKind::Convolution ? shading::defaultRecipe()
                                                                                                : shading::documentRecipe();
}

void requireRecipe(const BakeSettings& settings) {
    try {
        const auto& recipe = recipeOf(settings);
        if (recipe.weighting != shading::LobeWeighting::NdotL &&
            kernels::specularKindOf(settings.specularMethod) != kernels::SpecularKind::Convolution)
            throw BakeError(fmt::format("--recipe {} prefilters a lobe weighted by {}, which only --method convolution "
                                        "computes (--method {} prefilters the documents' N·L lobe)",
                                        recipe.name, shading::nameOf(recipe.weighting), settings.specularMethod));
    } catch (const std::invalid_argument& error) {
        throw BakeError(fmt::format("--recipe: {}", error.what()));
    }
}

// An engine finds a mip by its own lod mapping: a recipe of another mapping would give it mips
// prefiltered at roughnesses it does not ask for.
void requireProfileMapping(const BakeSettings& settings) {
    const auto& profile = profileOf(settings);
    if (profile.name == profiles::defaultProfile().name || !settings.recipe) return;
    const auto& own = shading::recipeNamed(profile.recipe);
    const auto& asked = shading::recipeNamed(*settings.recipe);
    if (asked.mapping != own.mapping || asked.mappingParameter != own.mappingParameter)
        throw BakeError(fmt::format("--recipe {} maps roughness to lod by {}, but --profile {} reads mips by {} "
                                    "(its recipe {})",
                                    asked.name, shading::nameOf(asked.mapping), profile.name,
                                    shading::nameOf(own.mapping), own.name));
}

uint32_t lutSampleCountOf(const BakeSettings& settings) {
    if (settings.lutSamples) return *settings.lutSamples;
    if (settings.lutMethod == kernels::kQuadratureGridLutMethod) return kernels::kDefaultLutGrid;
    if (settings.lutMethod == kernels::kFitLutMethod) return kDefaultLutFitDegree;
    return settings.lutMethod == kernels::kQuadratureLutMethod ? kernels::kDefaultQuadratureNodes : kDocumentSamples;
}

uint32_t sampleCountOf(const BakeSettings& settings) {
    if (settings.samples) return *settings.samples;
    switch (kernels::specularKindOf(settings.specularMethod)) {
    case kernels::SpecularKind::Convolution: return kDefaultConvolutionBudget;
    case kernels::SpecularKind::Pyramid: return kDefaultPyramidReads;
    case kernels::SpecularKind::MipChain: return 1;
    default: return kDocumentSamples;
    }
}

uint32_t mipCountOf(const BakeSettings& settings, const profiles::EngineProfile& profile, uint32_t size) {
    if (settings.mips) {
        requireRange("--mips", *settings.mips, 1, uint32_t(std::bit_width(size)));
        return *settings.mips;
    }
    return chainDownTo(size, profile.lastMipSize);
}

} // namespace

uint32_t chainDownTo(uint32_t size, uint32_t lastMipSize) {
    const uint32_t floor = std::clamp(lastMipSize, 1u, size);
    return uint32_t(std::bit_width(size)) - uint32_t(std::bit_width(floor)) + 1;
}

std::vector<float> roughnessOfMips(const shading::ShadingRecipe& recipe, uint32_t mips, uint32_t size) {
    const auto schedule = shading::scheduleOf(recipe, mips, size);
    std::vector<float> roughness;
    // The documents' recipe keeps their float expression, so that its maps stay bit for bit.
    for (uint32_t mip = 0; mip < mips; ++mip)
        roughness.push_back(recipe.mapping == shading::LodMapping::Linear ? roughnessOfMip(mip, mips)
                                                                          : float(schedule.roughnessOf(mip)));
    return roughness;
}

bool usesCache(const BakeSettings& settings) { return settings.cache && !settings.context.validation; }

ResolvedSettings resolveSettings(const BakeSettings& settings) {
    if (settings.size) {
        requireRange("--size", *settings.size, 1, kMaxCubeSize);
        requirePowerOfTwo("--size", *settings.size);
    }
    requireSpecularMethod(settings.specularMethod);
    if (settings.samples) requireRange("--samples", *settings.samples, 1, kernels::maxSamplesOf(settings.specularMethod));
    ResolvedSettings resolved{settings};
    resolved.engineProfile = &profileOf(settings);
    requireRecipe(settings);
    requireProfileMapping(settings);
    resolved.shadingRecipe = &recipeOf(settings);
    requireLutMethod(settings.lutMethod);
    if (settings.lutSamples) requireRange("--lut-samples", *settings.lutSamples, kernels::minLutSamplesOf(settings.lutMethod),
                     kernels::maxLutSamplesOf(settings.lutMethod));
    requireRange("--lut-size", settings.lutSize, 1, kMaxLutSize);
    requireRange("--irradiance-size", settings.irradianceSize, 1, kMaxIrradianceSize);
    resolved.sampleCount = sampleCountOf(settings);
    resolved.lutSampleCount = lutSampleCountOf(settings);
    // A chain asked without a size waits for the input's: a cube's own may be larger than the default.
    if (settings.size || !settings.mips) resolveFaceSize(resolved, 0);
    return resolved;
}

void resolveFaceSize(ResolvedSettings& settings, uint32_t inputCubeSize) {
    if (inputCubeSize == 0) {
        settings.faceSize = settings.size.value_or(kDefaultSize);
        settings.mipCount = mipCountOf(settings, *settings.engineProfile, settings.faceSize);
        return;
    }
    if (settings.size && *settings.size != inputCubeSize)
        throw BakeError("the input cube's faces are " + std::to_string(inputCubeSize) + "x" +
                        std::to_string(inputCubeSize) + "; --size " + std::to_string(*settings.size) +
                        " must match them or be left out");
    if (!std::has_single_bit(inputCubeSize))
        throw BakeError(fmt::format("the input cube's faces are {}x{}; the bake needs a power of two", inputCubeSize,
                                    inputCubeSize));
    settings.faceSize = inputCubeSize;
    settings.mipCount = mipCountOf(settings, *settings.engineProfile, inputCubeSize);
}

float roughnessOfMip(uint32_t mip, uint32_t mips) {
    return mips > 1 ? float(mip) / float(mips - 1) : 0.f;
}

} // namespace iblkit::bake
