#include "bake_cache.hpp"

#include "cache_key.hpp"
#include "fresh_memory.hpp"
#include "sha256.hpp"
#include "kernels/specular_method.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>

namespace iblkit::bake {
namespace {

using nlohmann::json;

std::string_view floatBytes(const std::vector<float>& values) {
    return {reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float)};
}

std::optional<std::pair<json, std::vector<float>>> splitPayload(std::string_view payload) {
    const size_t newline = payload.find('\n');
    if (newline == std::string_view::npos) return std::nullopt;
    auto header = json::parse(payload.substr(0, newline), nullptr, false);
    const auto bytes = payload.substr(newline + 1);
    if (header.is_discarded() || !header.is_object() || bytes.size() % sizeof(float) != 0) return std::nullopt;
    std::vector<float> values;
    image_io::resizePopulated(values, bytes.size() / sizeof(float));
    if (!bytes.empty()) std::memcpy(values.data(), bytes.data(), bytes.size()); // no copy from an empty view's null
    return std::pair{std::move(header), std::move(values)};
}

std::vector<std::string> sourceKernels(const EnvironmentInput& input) {
    if (input.kind == InputKind::BuiltIn) return {"SkyCubeCS", "DownsampleCubeCS"};
    if (input.kind == InputKind::Panorama) return {"EquirectToCubeCS", "DownsampleCubeCS"};
    return {"DownsampleCubeCS"};
}

std::vector<std::string> methodKernels(const std::string& method) {
    std::vector<std::string> names;
    for (const auto& kernel : kernels::kernelTable())
        if (kernel.belongsTo(method)) names.push_back(kernel.name);
    return names;
}

cache::CacheKey commonKey(const char* output, const vulkan::DeviceInfo& device, const std::string& toolVersion) {
    cache::CacheKey key;
    key.add("output", output).add("tool", toolVersion).add("program", cache::programDigest());
    key.add("device", device.name).add("driver", device.driver).add("api", device.apiVersion);
    return key;
}

// The source cube: the environment's bytes, the input policy, the size and the kernels that make it.
cache::CacheKey& addSource(cache::CacheKey& key, const EnvironmentInput& input, uint32_t size, const kernels::ShaderFiles& files) {
    // The input policies are left out: a bake they let through has the same source cube either way.
    key.add("input kind", std::string(inputKindName(input.kind)));
    for (const auto& file : input.files) key.add("input file", file.sha256);
    key.add("size", size);
    return key.add("source kernels", kernelSourcesDigest(sourceKernels(input), files));
}

// Which sources the recipe takes out as lights: what the residual every map is made from depends on.
cache::CacheKey& addLights(cache::CacheKey& key, const shading::ShadingRecipe& recipe) {
    if (!recipe.lights) return key.add("lights", "none");
    const auto& lights = *recipe.lights;
    return key.add("lights", fmt::format("above {:.17g} times the mean, at least {:.17g} of the light, within {:.17g} rad, at most {}",
                                         lights.threshold, lights.minShare, lights.maxRadius, lights.maxLights));
}

std::string roughnessList(const BakePlan& plan) {
    std::string list;
    for (const auto& mip : plan.mips) list += fmt::format("{:a} ", mip.roughness);
    return list;
}

} // namespace

std::string kernelSourcesDigest(const std::vector<std::string>& kernelNames, const kernels::ShaderFiles& files) {
    cache::CacheKey key;
    for (const auto& name : kernelNames) {
        const auto& kernel = kernels::kernelNamed(name);
        const auto source = kernel.options.source.generic_string();
        key.add("kernel", name).add(source, files.count(source) ? files.at(source) : "");
        for (const auto& [define, value] : kernel.options.defines) key.add("define " + define, value);
    }
    for (const auto& [path, text] : files)
        if (path.ends_with(".fxh")) key.add(path, text);
    return key.hex();
}

BakeKeys bakeKeys(const ResolvedSettings& settings, const EnvironmentInput& input, const BakePlan& plan,
                  const vulkan::DeviceInfo& device, const std::string& toolVersion, const kernels::ShaderFiles& files) {
    const uint32_t size = settings.faceSize;
    auto specular = commonKey("specular", device, toolVersion);
    addSource(specular, input, size, files)
        .add("method", settings.specularMethod)
        .add("samples", settings.sampleCount)
        .add("prefiltered mips", plan.prefilteredMips())
        .add("roughness of mips", roughnessList(plan))
        .add("lobe", std::string(shading::nameOf(plan.recipe->weighting)))
        .add("light level rule", fmt::format("{:.17g}", plan.recipe->lobeOverLight))
        .add("kernels", kernelSourcesDigest(methodKernels(settings.specularMethod), files))
        .add("cluster kernel", kernelSourcesDigest({"ClusterCubeCS"}, files)); // the convolution's pyramids
    addLights(specular, *plan.recipe);
    auto lut = commonKey("brdf lut", device, toolVersion);
    lut.add("method", settings.lutMethod).add("samples", settings.lutSampleCount).add("size", settings.lutSize);
    lut.add("kernels", kernelSourcesDigest(methodKernels(settings.lutMethod), files));
    auto irradiance = commonKey("irradiance", device, toolVersion);
    addSource(irradiance, input, size, files)
        .add("size", settings.irradianceSize)
        .add("cube", plan.irradiance)
        .add("kernels", kernelSourcesDigest({"ShProjectCS", "IrradianceCubeCS"}, files))
        .add("irradiance source", plan.recipe->irradianceSource);
    addLights(irradiance, *plan.recipe);
    auto lights = commonKey("lights", device, toolVersion);
    addLights(addSource(lights, input, size, files), *plan.recipe);
    auto lobeTable = commonKey("lobe table", device, toolVersion); // the program's digest holds its code
    lobeTable.add("weighting", std::string(shading::nameOf(plan.recipe->weighting))).add("size", shading::kLobeTableSize);
    BakeKeys keys{specular.hex(), lut.hex(), irradiance.hex(), lights.hex(), lobeTable.hex(), ""};
    auto preview = commonKey("preview", device, toolVersion);
    preview.add("specular", keys.specular).add("brdf lut", plan.lut ? keys.lut : "none").add("irradiance", keys.irradiance);
    preview.add("kernels", kernelSourcesDigest({"PreviewCS"}, files)).add("lights", keys.lights);
    const auto& recipe = *plan.recipe;
    preview.add("recipe", fmt::format("{} {} {:.17g} {} {}", shading::nameOf(recipe.weighting), shading::nameOf(recipe.mapping),
                                      recipe.mappingParameter, shading::nameOf(recipe.direction), shading::nameOf(recipe.lookup)));
    keys.preview = preview.hex();
    return keys;
}

// A JSON header line, then the floats.
FloatPayload texturePayload(const BakedTexture& texture) {
    return {json({{"name", texture.name}, {"format", int(texture.format)}, {"size", texture.size}, {"faces", texture.faces},
                  {"mips", texture.mips}})
                    .dump() +
                "\n",
            floatBytes(texture.values)};
}

// Larger than any size a bake accepts; it keeps a damaged entry's texel count from overflowing.
constexpr uint64_t kMaxPayloadTextureSize = 1u << 16;

std::optional<BakedTexture> textureFromPayload(std::string_view payload) {
    auto parts = splitPayload(payload);
    if (!parts) return std::nullopt;
    const json& header = parts->first; // not a structured binding: clang 14 cannot capture one
    // What the kit writes: a name, a known format, a size the bake allows, one face or six, and a
    // mip chain no longer than the size's. Anything else is a damaged entry, never a cast or shift
    // out of range.
    const auto wholeWithin = [&](const char* field, uint64_t low, uint64_t high) {
        const auto value = header.find(field);
        return value != header.end() && value->is_number_unsigned() && value->get<uint64_t>() >= low &&
               value->get<uint64_t>() <= high;
    };
    const auto name = header.find("name");
    if (name == header.end() || !name->is_string() || !wholeWithin("format", 0, uint64_t(image_io::PixelFormat::Rg32Float)) ||
        !wholeWithin("size", 1, kMaxPayloadTextureSize) || !wholeWithin("faces", 1, 6) || !wholeWithin("mips", 1, 32))
        return std::nullopt;
    BakedTexture texture{name->get<std::string>(), image_io::PixelFormat(header["format"].get<int>()), header["size"].get<uint32_t>(),
                         header["faces"].get<uint32_t>(), header["mips"].get<uint32_t>(), std::move(parts->second)};
    if (texture.faces != 1 && texture.faces != 6) return std::nullopt;
    size_t texels = 0;
    for (uint32_t mip = 0; mip < texture.mips; ++mip) texels += size_t(std::max(1u, texture.size >> mip)) * std::max(1u, texture.size >> mip);
    if (texture.values.size() != texels * texture.faces * image_io::channelCount(texture.format)) return std::nullopt;
    return texture;
}

FloatPayload irradiancePayload(const IrradianceSh& sh, const BakedTexture& cube) {
    json coefficients = json::array();
    for (const auto& c : sh.shRadiance) coefficients.push_back({c.r, c.g, c.b});
    auto payload = texturePayload(cube);
    payload.text = json({{"sh", coefficients}, {"solid_angle", sh.solidAngle}, {"sh_source", sh.shSourceSize},
                         {"cube_source", sh.cubeSourceSize}})
                       .dump() +
                   "\n" + payload.text;
    return payload;
}

std::optional<std::pair<IrradianceSh, BakedTexture>> irradianceFromPayload(std::string_view payload) {
    const size_t newline = payload.find('\n');
    if (newline == std::string_view::npos) return std::nullopt;
    const auto header = json::parse(payload.substr(0, newline), nullptr, false);
    auto cube = textureFromPayload(payload.substr(newline + 1));
    if (header.is_discarded() || !cube) return std::nullopt;
    try {
        IrradianceSh sh;
        for (size_t k = 0; k < 9; ++k) {
            const auto& c = header.at("sh").at(k);
            sh.shRadiance[k] = {c.at(0).get<double>(), c.at(1).get<double>(), c.at(2).get<double>()};
        }
        sh.solidAngle = header.at("solid_angle");
        for (const char* size : {"sh_source", "cube_source"})
            if (!header.at(size).is_number_unsigned() || header.at(size).get<uint64_t>() > kMaxPayloadTextureSize)
                return std::nullopt;
        sh.shSourceSize = header.at("sh_source");
        sh.cubeSourceSize = header.at("cube_source");
        return std::pair{sh, std::move(*cube)};
    } catch (const json::exception&) {
        return std::nullopt;
    }
}

std::string lightsPayload(const std::vector<shading::EnvironmentLight>& lights) {
    json list = json::array();
    for (const auto& light : lights)
        list.push_back({{"direction", {light.direction.x, light.direction.y, light.direction.z}},
                        {"radiance", {light.radiance.r, light.radiance.g, light.radiance.b}},
                        {"solid_angle", light.solidAngle},
                        {"angular_radius", light.angularRadius},
                        {"share", light.share}});
    return list.dump();
}

std::optional<std::vector<shading::EnvironmentLight>> lightsFromPayload(std::string_view payload) {
    const auto list = json::parse(payload, nullptr, false);
    if (list.is_discarded() || !list.is_array()) return std::nullopt;
    const auto vector = [](const json& value) {
        return glm::dvec3(value.at(0).get<double>(), value.at(1).get<double>(), value.at(2).get<double>());
    };
    std::vector<shading::EnvironmentLight> lights;
    try {
        for (const auto& light : list)
            lights.push_back({vector(light.at("direction")), vector(light.at("radiance")), light.at("solid_angle").get<double>(),
                              light.at("angular_radius").get<double>(), light.at("share").get<double>()});
    } catch (const json::exception&) {
        return std::nullopt;
    }
    return lights;
}

} // namespace iblkit::bake
