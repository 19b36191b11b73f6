#include "bake_manifest.hpp"

#include "file_names.hpp"
#include "kernels/sampled_methods.hpp"
#include "kernels/specular_method.hpp"

#include <fmt/core.h>

namespace iblkit::bake {

using nlohmann::json;

json coefficientsJson(const std::array<glm::dvec3, 9>& coefficients) {
    json list = json::array();
    for (const auto& c : coefficients) list.push_back({c.r, c.g, c.b});
    return list;
}

namespace {

json negativeRadianceJson(const EnvironmentInput& input, const BakeSettings& settings) {
    return {{"policy", settings.strict ? "refuse" : "clamp to 0"},
            {"texels", input.negative.count},
            {"most_negative", input.negative.mostNegative}};
}

json inputJson(const EnvironmentInput& input, const BakeSettings& settings) {
    json files = json::array();
    for (const auto& file : input.files) files.push_back({{"path", image_io::utf8Name(file.path)}, {"sha256", file.sha256}});
    json result = {{"kind", inputKindName(input.kind)}, {"files", files}};
    if (input.kind == InputKind::BuiltIn)
        result["rendered"] = fmt::format("SkyCubeCS straight into the cube, {}² evaluations per texel", kSkySupersample);
    else if (input.kind == InputKind::Panorama)
        result["panorama"] = {input.panorama.width, input.panorama.height};
    else
        result["cube_size"] = input.cubeSize;
    result["sanitized_texels"] = input.sanitizedTexels;
    result["negative_radiance"] = negativeRadianceJson(input, settings);
    return result;
}

json settingsJson(const ManifestFacts& facts) {
    const auto& s = *facts.settings;
    return {{"size", facts.size},
            {"mips", facts.mips},
            {"method", s.specularMethod},
            {"recipe", facts.plan->recipe->name},
            {"samples", s.sampleCount},
            {"lut_size", s.lutSize},
            {"lut_method", s.lutMethod},
            {"lut_samples", s.lutSampleCount},
            {"lut_format", s.lutFormat == LutFormat::Rg16Float ? "rg16f" : "rg32f"},
            {"irradiance_size", s.irradianceSize},
            {"dds", s.dds},
            {"exr", s.exr},
            {"sanitize", s.sanitize},
            {"strict", s.strict}};
}

// A sampled method's shader, or its chunked twin past the loop limit (see docs/kernels.md).
std::string sampledShader(kernels::KernelRole whole, kernels::KernelRole chunked, const std::string& method,
                          uint32_t samples) {
    const auto role = kernels::chunkSamplesFor(samples) ? chunked : whole;
    return kernels::kernelFor(role, method).options.source.generic_string();
}

uint32_t samplesPerDispatch(uint32_t samples) {
    const uint32_t chunk = kernels::chunkSamplesFor(samples);
    return chunk ? chunk : samples;
}

// The mip chain's mips: those copied from the source's own mips, and those the ring computed.
json mipChainJson(const std::string& method, uint32_t size, const BakePlan& plan) {
    json copied = json::array(), ring = json::array();
    for (const auto& mip : plan.mips)
        if (mip.mip > 0) (kernels::mipChainCopies(mip.roughness, size) ? copied : ring).push_back(mip.mip);
    return {{"method", method},
            {"mips_copied_from_the_source", copied},
            {"mips_from_the_ring", ring},
            {"shader", kernels::kernelFor(kernels::KernelRole::PrefilterRing, method).options.source.generic_string()}};
}

// How the prefilter method computed the mips: a sampled estimator's count and shader, a sample
// table's count at each mip, the pyramid's reads per texel, the mip chain's copied and ring mips,
// or the convolution's budget of terms per texel and its two shaders.
json prefilterJson(const ResolvedSettings& settings, uint32_t size, uint32_t mips, const BakePlan& plan) {
    const uint32_t samples = settings.sampleCount;
    const auto& method = settings.specularMethod;
    const auto kind = kernels::specularKindOf(method);
    if (kind == kernels::SpecularKind::Table) {
        json perMip = json::array(); // mips 1 and up
        for (uint32_t mip = 1; mip < mips; ++mip) perMip.push_back(kernels::tableSamplesAt(samples, mip));
        return {{"method", method},
                {"samples", samples},
                {"samples_of_mip", perMip},
                {"shader", kernels::kernelFor(kernels::KernelRole::PrefilterTable, method).options.source.generic_string()}};
    }
    if (kind == kernels::SpecularKind::Pyramid)
        return {{"method", method},
                {"reads_per_texel", samples},
                {"shader", kernels::kernelFor(kernels::KernelRole::PrefilterPyramid, method).options.source.generic_string()}};
    if (kind == kernels::SpecularKind::MipChain) return mipChainJson(method, size, plan);
    if (kind == kernels::SpecularKind::Convolution)
        return {{"method", method},
                {"terms_per_texel", samples},
                {"shader", kernels::kernelFor(kernels::KernelRole::PrefilterConvolution, method).options.source.generic_string()},
                {"pyramid_shader", kernels::kernelFor(kernels::KernelRole::ClusterCube).options.source.generic_string()}};
    return {{"method", method},
            {"samples", samples},
            {"samples_per_dispatch", samplesPerDispatch(samples)},
            {"shader", sampledShader(kernels::KernelRole::Prefilter, kernels::KernelRole::PrefilterChunk, method, samples)}};
}

// How the LUT method computed the LUT: the estimator's sample count or the quadrature's nodes per
// panel, and the shader.
json lutMethodJson(const ResolvedSettings& settings) {
    const uint32_t samples = settings.lutSampleCount;
    const auto& method = settings.lutMethod;
    if (method == kernels::kQuadratureGridLutMethod)
        return {{"method", method},
                {"grid_nodes_per_side", samples},
                {"nodes_per_panel", kernels::kDefaultQuadratureNodes},
                {"shaders", {kernels::kernelFor(kernels::KernelRole::BrdfLutGrid, method).options.source.generic_string(),
                             kernels::kernelFor(kernels::KernelRole::BrdfLutResample, method).options.source.generic_string()}}};
    if (method == kernels::kFitLutMethod)
        return {{"method", method},
                {"polynomial_degree", samples},
                {"shader", kernels::kernelFor(kernels::KernelRole::BrdfLut, method).options.source.generic_string()}};
    if (method == kernels::kQuadratureLutMethod)
        return {{"method", method},
                {"nodes_per_panel", samples},
                {"shader", kernels::kernelFor(kernels::KernelRole::BrdfLut, method).options.source.generic_string()}};
    return {{"method", method},
            {"samples", samples},
            {"samples_per_dispatch", samplesPerDispatch(samples)},
            {"shader", sampledShader(kernels::KernelRole::BrdfLut, kernels::KernelRole::BrdfLutChunk, method, samples)}};
}

json lutJson(const ResolvedSettings& s) {
    json lut = {{"file", "brdf_lut.ktx2"},
                {"format", s.lutFormat == LutFormat::Rg16Float ? "R16G16_SFLOAT" : "R32G32_SFLOAT"},
                {"size", s.lutSize},
                {"axes", "u = N.V, v = roughness, at texel centres; texel = (scale, bias) of F0"}};
    lut.update(lutMethodJson(s));
    return lut;
}

// How each mip's roughness follows from the lod mapping (runtime/shading/mip_schedule.hpp).
std::string scheduleText(const shading::MipSchedule& schedule) {
    const char* copied = "; mip 0 is the source cube, copied";
    switch (schedule.mapping) {
    case shading::LodMapping::Linear: return std::string("mip / (mips - 1)") + copied;
    case shading::LodMapping::Quadratic: return std::string("r with r (2 - r) = mip / (mips - 1)") + copied;
    case shading::LodMapping::Power:
        return fmt::format("r with r^{:g} = mip / (mips - 1){}", schedule.parameter, copied);
    case shading::LodMapping::Babylon: return std::string("r with 0.8 log2(r² size) = mip") + copied;
    case shading::LodMapping::Logarithmic:
        return fmt::format("r with lod = k log2(r² size) + b = mip: mip 1 at r² = {:.6g} / size, the last at r = 1{}",
                           schedule.parameter, copied);
    }
    return copied;
}

json lightsJson(const std::vector<shading::EnvironmentLight>& lights) {
    json list = json::array();
    for (const auto& light : lights)
        list.push_back({{"direction", {light.direction.x, light.direction.y, light.direction.z}},
                        {"radiance", {light.radiance.r, light.radiance.g, light.radiance.b}},
                        {"angular_radius", light.angularRadius},
                        {"solid_angle", light.solidAngle},
                        {"share_of_the_light", light.share}});
    return list;
}

json specularJson(const ManifestFacts& facts) {
    json roughness = json::array();
    for (const auto& mip : facts.plan->mips) roughness.push_back(mip.roughness);
    const auto& schedule = facts.plan->schedule;
    json specular = {{"file", "specular.ktx2"},
                     {"format", "R16G16B16A16_SFLOAT"},
                     {"size", facts.size},
                     {"mips", facts.mips},
                     {"roughness_of_mip", scheduleText(schedule)},
                     {"roughness", roughness},
                     {"lobe_weighting", shading::nameOf(facts.plan->recipe->weighting)}};
    specular.update(prefilterJson(*facts.settings, facts.size, facts.mips, *facts.plan));
    return specular;
}

json irradianceJson(const ManifestFacts& facts) {
    const auto& irradiance = *facts.irradiance;
    return {{"file", "irradiance.ktx2"},
            {"format", "R16G16B16A16_SFLOAT"},
            {"size", facts.settings->irradianceSize},
            {"texel", "E(n) / pi: multiply by albedo for Lambertian diffuse"},
            {"of", facts.lights->empty() ? "the environment"
                                         : "the environment without its lights (shading.lights), plus at each texel the lights' "
                                           "texels' exact irradiance less their disks': add their diffuse as a disk's (IblDiskLight)"},
            {"source_mip_size", irradiance.cubeSourceSize},
            {"source", "per texel of the source mip, its radiance times solid angle and its luminance-weighted mean "
                       "direction, summed on the host from the mip up to 8 times finer"},
            {"shader", "hlsl/IrradianceCubeCS.hlsl"},
            {"sh",
             {{"basis", "real spherical harmonics l <= 2 in the order (0,0) (1,-1) (1,0) (1,1) (2,-2) (2,-1) (2,0) "
                        "(2,1) (2,2); Y_1-1 ~ y, Y_10 ~ z, Y_11 ~ x (hlsl/Common/SphericalHarmonics.fxh)"},
              {"radiance", coefficientsJson(irradiance.shRadiance)},
              {"irradiance_over_pi", coefficientsJson(irradianceCoefficients(irradiance.shRadiance))},
              {"source_mip_size", irradiance.shSourceSize},
              {"shader", "hlsl/ShProjectCS.hlsl"}}}};
}

} // namespace

std::array<glm::dvec3, 9> irradianceCoefficients(const std::array<glm::dvec3, 9>& radiance) {
    std::array<glm::dvec3, 9> result;
    for (size_t k = 0; k < 9; ++k) result[k] = radiance[k] * (k == 0 ? 1.0 : k < 4 ? 2.0 / 3.0 : 0.25);
    return result;
}

size_t clampedValueCount(const std::vector<HalfRangeClamp>& clamps) {
    size_t total = 0;
    for (const auto& clamp : clamps) total += clamp.values;
    return total;
}

json halfRangeClampsJson(const std::vector<HalfRangeClamp>& clamps) {
    json list = json::array();
    for (const auto& clamp : clamps)
        list.push_back({{"texture", clamp.texture},
                        {"clamped_values", clamp.values},
                        {"worst_mip", clamp.worstMip},
                        {"share_of_its_energy_lost", clamp.worstShare}});
    return list;
}

namespace {

json halfRangeJson(const std::vector<HalfRangeClamp>& clamps, const BakeSettings& settings) {
    return {{"policy", settings.strict ? "refuse" : "clamp to 65504"},
            {"clamped_values", clampedValueCount(clamps)},
            {"textures", halfRangeClampsJson(clamps)}};
}

} // namespace

namespace {

// The specular entry as the plan made it: the prefiltered mips, and the mips no material reads,
// filled with the source's own.
json plannedSpecularJson(const ManifestFacts& facts) {
    json specular = specularJson(facts);
    json prefiltered = json::array(), filled = json::array();
    for (const auto& mip : facts.plan->mips) (mip.needed || mip.mip == 0 ? prefiltered : filled).push_back(mip.mip);
    specular["prefiltered_mips"] = prefiltered;
    if (!filled.empty())
        specular["filled_mips"] = {{"mips", filled},
                                   {"with", "the source cube's own mip (2x2 means of mip 0): loadable, not prefiltered, "
                                            "since no material of the scene reads it"}};
    return specular;
}

json skippedJson(const std::string& why) { return {{"file", nullptr}, {"skipped", why}}; }

} // namespace

bool readsLobeTable(const shading::ShadingRecipe& recipe) {
    return recipe.direction == shading::LookupDirection::Fitted || recipe.lookup != shading::LookupLobe::Roughness;
}

json shadingJson(const ManifestFacts& facts) {
    const auto& recipe = *facts.plan->recipe;
    const auto& schedule = facts.plan->schedule;
    json roughness = json::array();
    for (const auto& mip : facts.plan->mips) roughness.push_back(mip.roughness);
    const auto& lights = *facts.lights;
    json taken = nullptr;
    if (recipe.lights)
        taken = {{"threshold_over_mean_luminance", recipe.lights->threshold},
                 {"min_share_of_the_light", recipe.lights->minShare},
                 {"max_angular_radius", recipe.lights->maxRadius},
                 {"max_lights", recipe.lights->maxLights}};
    json lobeTable = nullptr;
    if (facts.lobeTableFile)
        lobeTable = {{"file", "lobe_table.ktx2"},
                     {"format", "R32G32B32A32_SFLOAT"},
                     {"size", shading::kLobeTableSize},
                     {"axes", "u = N.V, v = roughness, at texel centres; texel = (blend towards R, roughness, pair "
                              "roughness, pair spread in radians)"}};
    return {{"recipe", recipe.name},
            {"function", "hlsl/Common/ImageBasedLighting.fxh: IblShadeOpaque, plus IblDiskLight for each light"},
            {"lobe_weighting", shading::nameOf(recipe.weighting)},
            {"lod_mapping", shading::nameOf(schedule.mapping)},
            {"lod_parameter", schedule.parameter},
            {"roughness_of_mip", scheduleText(schedule)},
            {"roughness", roughness},
            {"direction", shading::nameOf(recipe.direction)},
            {"lookup", shading::nameOf(recipe.lookup)},
            {"lobe_table", lobeTable},
            {"lights_taken_out", taken},
            {"light_level", facts.lightLevel},
            {"lights", {{"file", lights.empty() ? json(nullptr) : json("lights.gltf")}, {"list", lightsJson(lights)}}},
            {"ibl_recipe", {{"LodMapping", uint32_t(schedule.mapping)},
                            {"LodParameter", schedule.parameter},
                            {"SpecularMips", facts.mips},
                            {"SpecularSize", facts.size},
                            {"Direction", uint32_t(recipe.direction)},
                            {"Lookup", uint32_t(recipe.lookup)},
                            {"LightCount", lights.size()},
                            {"LightLevel", facts.lightLevel}}}};
}

namespace {

// E(n)/π = Σ c_i P_i(n) over the plain polynomials P = 1, y, z, x, xy, yz, 3z² - 1, xz, x² - y²:
// each radiance coefficient times A_l/π (Ramamoorthi and Hanrahan) and its basis constant.
std::array<glm::dvec3, 9> shaderCoefficients(const std::array<glm::dvec3, 9>& radiance) {
    constexpr std::array<double, 9> basis = {0.282094791773878, 0.488602511902920, 0.488602511902920,
                                             0.488602511902920, 1.092548430592079, 1.092548430592079,
                                             0.315391565252520, 1.092548430592079, 0.546274215296040};
    auto coefficients = irradianceCoefficients(radiance);
    for (size_t i = 0; i < 9; ++i) coefficients[i] *= basis[i];
    return coefficients;
}

const char* specularFileJson(profiles::SpecularFile file) {
    switch (file) {
    case profiles::SpecularFile::Ktx2: return "specular.ktx2";
    case profiles::SpecularFile::Dds: return "specular.dds";
    case profiles::SpecularFile::Ktx1: return "specular.ktx";
    }
    return "";
}

const char* frameJson(profiles::CubeFrame frame) {
    switch (frame) {
    case profiles::CubeFrame::Kit: return "the kit's: the texel at direction g holds the radiance from g";
    case profiles::CubeFrame::MirroredX:
        return "mirrored in x: the texel at direction g holds the radiance from (-g.x, g.y, g.z), for an engine that negates x";
    case profiles::CubeFrame::MirroredZ:
        return "mirrored in z: the texel at direction g holds the radiance from (g.x, g.y, -g.z), for an engine whose cubes are left-handed";
    }
    return "";
}

const char* diffuseJson(profiles::DiffuseSource source) {
    switch (source) {
    case profiles::DiffuseSource::IrradianceMap: return "irradiance.ktx2 (E/pi) or the SH";
    case profiles::DiffuseSource::LastSpecularMip: return "pi times the specular cube's last mip";
    case profiles::DiffuseSource::EngineSh: return "the engine's own SH, projected from the specular cube's mip 0";
    }
    return "";
}

json profileJson(const profiles::EngineProfile& profile) {
    return {{"name", profile.name},
            {"engine", profile.engine},
            {"recipe", profile.recipe},
            {"cube_frame", frameJson(profile.frame)},
            {"last_mip_size", profile.lastMipSize},
            {"lod", profile.lodFormula},
            {"lookup", profile.lookup},
            {"specular_file", specularFileJson(profile.file)},
            {"diffuse", diffuseJson(profile.diffuse)},
            {"brdf_lut", profile.readsKitLut ? "brdf_lut.ktx2" : "the engine's own (brdf_lut.ktx2 is the kit's)"},
            {"sh", profile.shForm},
            {"lights", profile.lightsForm},
            {"loader", profile.loader}};
}

} // namespace

json bakeManifest(const ManifestFacts& facts) {
    const auto& s = *facts.settings;
    const auto& plan = *facts.plan;
    json irradiance = irradianceJson(facts);
    if (!plan.irradiance) {
        auto sh = std::move(irradiance.at("sh"));
        irradiance = skippedJson("every lit material of the scene is all metal (or none is lit)");
        irradiance["sh"] = std::move(sh);
    }
    json manifest = {{"generator", "iblkit"},
                     {"command", "bake"},
                     {"version", facts.toolVersion},
                     {"manifest_format", 1},
                     {"device", facts.device},
                     {"input", inputJson(*facts.input, s)},
                     {"settings", settingsJson(facts)},
                     {"specular", plan.specular ? plannedSpecularJson(facts) : skippedJson("no material of the scene is lit")},
                     {"brdf_lut", plan.lut ? lutJson(s) : skippedJson("no material of the scene is lit")},
                     {"irradiance", irradiance},
                     {"shading", shadingJson(facts)},
                     {"profile", profileJson(*s.engineProfile)},
                     {"half_range", halfRangeJson(*facts.halfRangeClamps, s)},
                     {"preview", {{"file", "preview.png"}, {"exposure", facts.previewExposure}}}};
    if (const auto& profile = *s.engineProfile; profile.shCoefficients == profiles::ShForm::IrradianceShader)
        manifest["profile"]["sh_coefficients"] = coefficientsJson(shaderCoefficients(facts.irradiance->shRadiance));
    if (plan.scene) manifest["plan"] = planJson(plan);
    return manifest;
}

json filesJson(const std::vector<WrittenFile>& files) {
    json list = json::array();
    for (const auto& file : files) list.push_back({{"name", file.name}, {"sha256", file.sha256}, {"bytes", file.bytes}});
    return list;
}

} // namespace iblkit::bake
