#include "bake_plan.hpp"

#include "environment_input.hpp"
#include "kernels/kernel_table.hpp"
#include "kernels/specular_method.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace iblkit::bake {
namespace {

struct SceneUse {
    bool anyLit = false, anyTransmission = false, anyNonMetal = false;
    scene::ValueRange roughness;               // the hull of every range below
    std::vector<scene::ValueRange> roughnesses; // each lit material's, and each clearcoat's: gaps between them are skipped
    size_t unlit = 0;
};

SceneUse useOf(const std::optional<scene::SceneMaterials>& scene) {
    SceneUse use;
    if (!scene) return {true, false, true, scene::ValueRange::of(0, 1), {scene::ValueRange::of(0, 1)}, 0};
    for (const auto& material : scene->materials) {
        if (material.unlit) {
            ++use.unlit;
            continue;
        }
        use.anyLit = true;
        use.anyTransmission = use.anyTransmission || material.transmission;
        use.anyNonMetal = use.anyNonMetal || material.metalness.min < 1;
        for (const auto& range : {material.roughness, material.clearcoatRoughness})
            if (!range.empty()) {
                use.roughness.include(range);
                use.roughnesses.push_back(range);
            }
    }
    return use;
}

// Whether a renderer reading roughness `used` touches mip m of the chain (up to its neighbours).
bool bracketMeets(const scene::ValueRange& used, uint32_t mip, const std::vector<float>& roughness) {
    if (used.empty()) return false;
    // In float, as the mips' roughness is: a roughness on a mip (0.8 on the documents' mip 4) is that mip's alone.
    const float below = mip == 0 ? -1.f : roughness[mip - 1];
    const float above = mip + 1 == roughness.size() ? 2.f : roughness[mip + 1];
    return float(used.min) < above && float(used.max) > below;
}

double texelsOfChain(uint32_t size, uint32_t mips, uint32_t firstMip) {
    double texels = 0;
    for (uint32_t mip = firstMip; mip < mips; ++mip) texels += std::pow(double(std::max(1u, size >> mip)), 2);
    return texels;
}

void planSpecularMips(const ResolvedSettings& settings, const SceneUse& use, const BenchCurves& curves,
                      BakePlan& plan) {
    const uint32_t size = settings.faceSize, mips = settings.mipCount;
    const auto roughness = roughnessOfMips(*plan.recipe, mips, size);
    const bool benchLobe = plan.recipe->weighting == shading::LobeWeighting::NdotL;
    const auto curve = curves.curve("specular", settings.specularMethod, settings.sampleCount);
    const uint32_t benchMips = chainDownTo(curves.cubeSize(), profiles::defaultProfile().lastMipSize);
    const double benchTexels = texelsOfChain(curves.cubeSize(), benchMips, 1);
    double neededMs = 0;
    for (uint32_t mip = 0; mip < mips; ++mip) {
        SpecularMipPlan mipPlan;
        mipPlan.mip = mip;
        mipPlan.roughness = roughness[mip];
        mipPlan.faceSize = std::max(1u, size >> mip);
        mipPlan.needed = plan.specular && (use.anyTransmission || std::any_of(use.roughnesses.begin(), use.roughnesses.end(),
                                                                               [&](const auto& used) { return bracketMeets(used, mip, roughness); }));
        if (curve) {
            // Mip 0 is the source copied; the others cost in proportion to their texels.
            mipPlan.estimate.deviceMs = mip == 0 ? 0.0 : curve->medianDeviceMs * std::pow(double(mipPlan.faceSize), 2) / benchTexels;
            for (const auto& [benchMip, error] : curve->worstMipError)
                if (benchLobe && std::fabs(roughnessOfMip(benchMip, benchMips) - mipPlan.roughness) < 1e-6) {
                    mipPlan.estimate.errorRms = error.first;
                    mipPlan.estimate.errorMax = error.second;
                }
            if (mipPlan.needed) neededMs += *mipPlan.estimate.deviceMs;
        }
        plan.mips.push_back(mipPlan);
    }
    if (!curve) return;
    // The error of what is baked: the worst needed mip's, and none when the bench measured no mip
    // at some needed roughness (another mip count).
    plan.specularEstimate.deviceMs = neededMs;
    const bool everyNeededMipMeasured = std::all_of(plan.mips.begin(), plan.mips.end(), [](const SpecularMipPlan& mip) {
        return !mip.needed || mip.mip == 0 || mip.estimate.errorRms;
    });
    if (!everyNeededMipMeasured) return;
    for (const auto& mip : plan.mips) {
        if (!mip.needed || !mip.estimate.errorRms) continue;
        plan.specularEstimate.errorRms = std::max(plan.specularEstimate.errorRms.value_or(0), *mip.estimate.errorRms);
        plan.specularEstimate.errorMax = std::max(plan.specularEstimate.errorMax.value_or(0), *mip.estimate.errorMax);
    }
}

Estimate scaledEstimate(const std::optional<MeasuredCurve>& curve, double texelRatio) {
    if (!curve) return {};
    return {curve->medianDeviceMs * texelRatio, curve->worstErrorRms, curve->worstErrorMax};
}

void planLut(const ResolvedSettings& settings, const SceneUse& use, const BenchCurves& curves, BakePlan& plan) {
    const double n = settings.lutSize;
    if (!use.roughness.empty()) {
        plan.lutFirstRow = uint32_t(std::clamp(std::floor(use.roughness.min * n - 0.5), 0.0, n - 1));
        plan.lutLastRow = uint32_t(std::clamp(std::floor(use.roughness.max * n - 0.5) + 1, 0.0, n - 1));
    }
    if (plan.lut)
        plan.lutEstimate = scaledEstimate(curves.curve("lut", settings.lutMethod, settings.lutSampleCount),
                                          std::pow(n / curves.lutSize(), 2));
}

void listKernels(const ResolvedSettings& settings, BakePlan& plan) {
    const auto add = [&](const std::string& name, const std::string& permutation = "") {
        plan.kernels.push_back(permutation.empty() ? name : name + " (" + permutation + ")");
    };
    // A cube input (.ktx2, .dds, a folder of faces) is uploaded as it is: no conversion kernel.
    if (!settings.environment) add("SkyCubeCS");
    else if (!isCubeInput(*settings.environment)) add("EquirectToCubeCS");
    add("DownsampleCubeCS");
    if (plan.specular && kernels::isConvolutionMethod(settings.specularMethod)) add("ClusterCubeCS"); // its pyramids
    for (const auto& kernel : kernels::kernelTable()) {
        if (plan.specular && kernel.belongsTo(settings.specularMethod))
            add(kernel.name, fmt::format("{} {}", settings.specularMethod, settings.sampleCount));
        if (plan.lut && kernel.belongsTo(settings.lutMethod))
            add(kernel.name, fmt::format("{} {}", settings.lutMethod, settings.lutSampleCount));
    }
    // Both irradiance kernels are compiled even when the cube is skipped: the SH projection runs
    // for the manifest and the preview's exposure.
    add("ShProjectCS");
    add("IrradianceCubeCS");
    add("PreviewCS");
}

void explain(const std::optional<scene::SceneMaterials>& scene, const SceneUse& use, BakePlan& plan) {
    if (!scene) {
        plan.reasons.push_back("no scene: every output, every mip");
        return;
    }
    const size_t lit = scene->materials.size() - use.unlit;
    plan.reasons.push_back(fmt::format("{} materials, {} lit, {} unlit", scene->materials.size(), lit, use.unlit));
    if (!use.anyLit) plan.reasons.push_back("no lit material: no specular chain, no LUT, no irradiance");
    else if (!use.anyNonMetal) plan.reasons.push_back("every lit material is all metal: no irradiance");
    if (use.anyTransmission) plan.reasons.push_back("a material transmits light: the whole specular chain");
}


NeededOutputs outputsFor(const SceneUse& use) { return {use.anyLit, use.anyNonMetal, use.anyLit}; }

} // namespace

std::vector<bool> BakePlan::prefilteredMips() const {
    std::vector<bool> prefiltered;
    for (const auto& mip : mips) prefiltered.push_back(mip.needed);
    return prefiltered;
}

NeededOutputs neededOutputs(const std::optional<scene::SceneMaterials>& scene) { return outputsFor(useOf(scene)); }

BakePlan planBake(const ResolvedSettings& settings, const std::optional<scene::SceneMaterials>& scene,
                  const BenchCurves& curves) {
    const auto use = useOf(scene);
    BakePlan plan;
    if (scene) {
        plan.scene = scene->file;
        plan.unknownExtensions = scene->unknownExtensions;
        plan.notes = scene->notes;
        for (const auto& material : scene->materials) {
            for (const auto& note : material.notes) plan.notes.push_back(material.name + ": " + note);
            for (const auto& extension : material.unknownExtensions)
                plan.notes.push_back(material.name + ": " + extension + " is not understood: its lighting needs are not counted");
        }
    }
    plan.roughness = use.roughness;
    plan.recipe = settings.shadingRecipe;
    plan.schedule = shading::scheduleOf(*plan.recipe, settings.mipCount, settings.faceSize);
    const auto outputs = outputsFor(use);
    plan.specular = outputs.specular;
    plan.lut = outputs.lut;
    plan.irradiance = outputs.irradiance;
    planSpecularMips(settings, use, curves, plan);
    planLut(settings, use, curves, plan);
    if (plan.irradiance)
        plan.irradianceEstimate = scaledEstimate(curves.curve("irradiance", "exact-sum", 0),
                                                 std::pow(double(settings.irradianceSize) / curves.irradianceSize(), 2));
    listKernels(settings, plan);
    explain(scene, use, plan);
    return plan;
}

} // namespace iblkit::bake
