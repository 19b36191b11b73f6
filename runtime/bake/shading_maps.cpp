#include "shading_maps.hpp"

#include "gpu_steps.hpp"
#include "image_transfer.hpp"
#include "kernels/kernel_steps.hpp"
#include "reference_irradiance.hpp"
#include "shading/built_glass_tables.hpp"
#include "shading/built_lobe_tables.hpp"
#include "shading/disk_light.hpp"
#include "shading/sphere_transmission.hpp"
#include "shading/transmission_table.hpp"

#include <algorithm>
#include <map>
#include <mutex>
#include <span>

namespace iblkit::bake {

namespace {

// The source's texels that the extraction changed, as light texels and as the residual's values.
struct ChangedTexels {
    std::vector<reference::CubeTexelRadiance> light;
    std::vector<vulkan::TexelAt> where;
    std::vector<float> residual;
};

ChangedTexels changedTexels(const shading::Extraction& extraction, uint32_t size) {
    ChangedTexels changed;
    for (const auto& [texel, taken] : extraction.taken) {
        changed.light.push_back({uint32_t(texel), taken});
        changed.where.push_back({uint32_t(texel / (size_t(size) * size)), uint32_t(texel / size % size), uint32_t(texel % size)});
        const float* after = &extraction.residual[4 * texel];
        changed.residual.insert(changed.residual.end(), after, after + 4);
    }
    return changed;
}

} // namespace

TakenOutLights takeOutLights(const vulkan::VulkanContext& context, const vulkan::Image& source,
                             const shading::ExtractionSettings& settings, kernels::Kernel& downsample, BakeProgress& progress) {
    progress.begin("lights");
    const uint32_t size = source.desc().width;
    auto extraction = shading::extractLights(vulkan::downloadMip(context, source, 0), size, settings);
    TakenOutLights result{std::move(extraction.lights), std::nullopt, {}, {}};
    if (result.lights.empty()) {
        result.restMipZero = std::move(extraction.residual);
        progress.end();
        return result;
    }
    progress.advance(0.8, "residual");
    auto changed = changedTexels(extraction, size);
    result.lightTexels = std::move(changed.light);
    // The residual is the source but for the lights' few texels: copied on the device, those written over it.
    auto& residual = result.residual.emplace(
        context, vulkan::ImageDesc{"Residual", source.desc().format, size, size, 6, vulkan::fullMipCount(size, size), true, true});
    progress.addDeviceTime(std::max(0.0, residual.copyMipFrom(context, source, 0).deviceMilliseconds));
    vulkan::writeTexels(context, residual, 0, changed.where, changed.residual);
    kernels::runDownsampleChain(downsample, residual);
    progress.addDeviceTime(downsample.takeTotals().deviceMilliseconds);
    result.restMipZero = std::move(extraction.residual);
    progress.end();
    return result;
}

void addLightTexelsIrradiance(const vulkan::VulkanContext& context, vulkan::Image& irradiance, const TakenOutLights& taken) {
    if (taken.lights.empty()) return;
    const uint32_t size = irradiance.desc().width;
    const auto exact = reference::exactIrradianceCube(taken.lightTexels, taken.residual->desc().width, size);
    auto values = irradiance.download(context);
    for (size_t texel = 0; texel < exact.size(); ++texel) {
        const auto face = uint32_t(texel / (size_t(size) * size));
        const auto normal = reference::cubeTexelCentre(face, uint32_t(texel % size), uint32_t(texel / size % size), size);
        glm::dvec3 difference = exact[texel];
        for (const auto& light : taken.lights) difference -= shading::diskIrradianceOverPi(light, normal);
        for (int c = 0; c < 3; ++c) values[4 * texel + size_t(c)] = float(std::max(0.0, values[4 * texel + size_t(c)] + difference[c]));
    }
    irradiance.upload(context, values);
}

vulkan::Image lobeTableImage(const vulkan::VulkanContext& context, shading::LobeWeighting weighting) {
    const uint32_t size = shading::kLobeTableSize;
    vulkan::Image table(context, {"LobeTable", &vulkan::texelFormatNamed("R32G32B32A32_SFLOAT"), size, size, 1, 1, false, false});
    table.upload(context, shading::builtLobeTable(weighting));
    return table;
}

namespace {

template <typename Compute>
const std::vector<float>& computedOnce(uint32_t size, const Compute& compute) {
    static std::mutex mutex;
    static std::map<uint32_t, std::vector<float>> tables;
    const std::lock_guard lock(mutex);
    auto found = tables.find(size);
    if (found == tables.end()) found = tables.emplace(size, compute(size)).first;
    return found->second;
}

// The committed table at kTransmissionTableSize (built_glass_tables.hpp), else `compute`'s.
std::vector<float> committedOr(uint32_t size, std::span<const float> committed, std::vector<float> (*compute)(uint32_t)) {
    return size == shading::kTransmissionTableSize ? std::vector<float>(committed.begin(), committed.end()) : compute(size);
}

vulkan::Image layeredTable(const vulkan::VulkanContext& context, const char* name, const char* format, uint32_t size,
                           const std::vector<float>& values) {
    const auto layers = uint32_t(shading::kTransmissionEtas.size());
    vulkan::Image table(context, {name, &vulkan::texelFormatNamed(format), size, size * layers, 1, 1, false, false});
    table.upload(context, values);
    return table;
}

} // namespace

const std::vector<float>& transmissionTableOf(uint32_t size) {
    return computedOnce(size, [](uint32_t n) { return committedOr(n, shading::builtTransmissionTable(), shading::transmissionTable); });
}

const std::vector<float>& sphereTransmissionTableOf(uint32_t size) {
    return computedOnce(size, [](uint32_t n) {
        return committedOr(n, shading::builtSphereTransmissionTable(), shading::sphereTransmissionTable);
    });
}

uint32_t transmissionTableSize(shading::GlassTransmission transmission) {
    return transmission == shading::GlassTransmission::Tabulated ? shading::kTransmissionTableSize : 1;
}

uint32_t sphereTransmissionTableSize(shading::GlassTransmission transmission) {
    return transmission == shading::GlassTransmission::Sphere ? shading::kTransmissionTableSize : 1;
}

GlassTables glassTables(const vulkan::VulkanContext& context, shading::GlassTransmission transmission) {
    const uint32_t interfaceSize = transmissionTableSize(transmission), sphereSize = sphereTransmissionTableSize(transmission);
    return {layeredTable(context, "TransmissionTable", "R32G32_SFLOAT", interfaceSize, transmissionTableOf(interfaceSize)),
            layeredTable(context, "SphereTransmissionTable", "R32G32B32A32_SFLOAT", sphereSize, sphereTransmissionTableOf(sphereSize))};
}

std::vector<float> packEnvironmentLights(const std::vector<shading::EnvironmentLight>& lights) {
    std::vector<float> values;
    for (const auto& light : lights)
        values.insert(values.end(), {float(light.direction.x), float(light.direction.y), float(light.direction.z),
                                     float(light.angularRadius), float(light.radiance.r), float(light.radiance.g),
                                     float(light.radiance.b), float(light.solidAngle)});
    if (values.empty()) values.assign(8, 0.f);
    return values;
}

vulkan::Buffer environmentLightBuffer(const vulkan::VulkanContext& context, const std::vector<shading::EnvironmentLight>& lights) {
    const auto packed = packEnvironmentLights(lights);
    return vulkan::storageBuffer(context, std::as_bytes(std::span(packed)), "Lights");
}

kernels::IblRecipeParameters recipeParameters(const shading::ShadingRecipe& recipe, const shading::MipSchedule& schedule,
                                              size_t lightCount, uint32_t lightLevel) {
    return {schedule.size,           uint32_t(schedule.mapping), float(schedule.parameter), uint32_t(recipe.direction),
            uint32_t(recipe.lookup), uint32_t(lightCount),       lightLevel};
}

} // namespace iblkit::bake
