#include "api/baked_maps.hpp"

#include <algorithm>

namespace iblkit::api {
namespace {

std::array<double, 3> rgb(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

// A cube's values (order mip, face, row, column, channel) as its mips of six faces.
std::vector<CubeMip> cubeMipsOf(const bake::BakedTexture& texture) {
    const uint32_t channels = image_io::channelCount(texture.format);
    std::vector<CubeMip> mips;
    auto at = texture.values.begin();
    for (uint32_t mip = 0; mip < texture.mips; ++mip) {
        CubeMip level;
        level.size = std::max(1u, texture.size >> mip);
        const size_t faceValues = size_t(level.size) * level.size * channels;
        for (auto& face : level.faces) {
            face.assign(at, at + std::ptrdiff_t(faceValues));
            at += std::ptrdiff_t(faceValues);
        }
        mips.push_back(std::move(level));
    }
    return mips;
}

Image2D imageOf(bake::BakedTexture& texture) {
    return {texture.size, texture.size, image_io::channelCount(texture.format), std::move(texture.values)};
}

EnvironmentLight lightOf(const shading::EnvironmentLight& light) {
    return {rgb(light.direction), rgb(light.radiance), light.solidAngle, light.angularRadius, light.share};
}

} // namespace

std::array<std::array<double, 3>, 9> shCoefficientsOf(const std::array<glm::dvec3, 9>& coefficients) {
    std::array<std::array<double, 3>, 9> result;
    std::transform(coefficients.begin(), coefficients.end(), result.begin(), rgb);
    return result;
}

BakedMaps bakedMapsOf(bake::ComputedMaps maps, const bake::BakePlan& plan) {
    auto& outputs = maps.outputs;
    BakedMaps result;
    if (outputs.specular) {
        result.specular = cubeMipsOf(*outputs.specular);
        for (const auto& mip : plan.mips) result.specularRoughness.push_back(mip.roughness);
    }
    if (outputs.lut) result.brdfLut = imageOf(*outputs.lut);
    if (outputs.irradiance) result.irradiance = cubeMipsOf(*outputs.irradiance).front();
    if (outputs.lobeTable) result.lobeTable = imageOf(*outputs.lobeTable);
    std::transform(outputs.lights.begin(), outputs.lights.end(), std::back_inserter(result.lights), lightOf);
    result.shRadiance = shCoefficientsOf(outputs.sh.shRadiance);
    result.shading = std::move(maps.shadingRecord);
    result.device = outputs.device;
    return result;
}

} // namespace iblkit::api
