#include "suite_inputs.hpp"

#include "cube_environment.hpp"
#include "reference_bake.hpp"
#include "shading_maps.hpp"
#include "shading/built_lobe_tables.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace iblkit::consistency {
MippedCube environmentCube(const SuiteEnvironment& environment, uint32_t size, uint32_t mips) {
    MippedCube cube{size, mips, environment.cube(size)};
    std::vector<float> level = cube.texels;
    for (uint32_t mip = 1; mip < mips; ++mip) {
        level = reference::downsampleCubeInFloat(level, cube.mipSize(mip - 1));
        cube.texels.insert(cube.texels.end(), level.begin(), level.end());
    }
    return cube;
}

SuiteEnvironment testSuiteEnvironment() {
    const auto panorama = [](uint32_t width) {
        Panorama panorama{width, width / 2, {}};
        panorama.texels.reserve(size_t(width) * panorama.height * 4);
        for (uint32_t y = 0; y < panorama.height; ++y)
            for (uint32_t x = 0; x < width; ++x) {
                const double longitude = ((x + 0.5) / width - 0.5) * 2 * std::numbers::pi;
                const double latitude = (y + 0.5) / panorama.height * std::numbers::pi;
                const glm::dvec3 direction(std::sin(latitude) * std::sin(longitude), std::cos(latitude),
                                           -std::sin(latitude) * std::cos(longitude));
                const glm::dvec3 radiance = reference::CubeEnvironment::testRadiance(direction);
                panorama.texels.insert(panorama.texels.end(), {float(radiance.r), float(radiance.g), float(radiance.b), 1.f});
            }
        return panorama;
    };
    return {"the test environment",
            [](uint32_t size) { return reference::CubeEnvironment::testEnvironment(size).texels(); }, panorama};
}

PreviewInputs previewInputs(const SuiteEnvironment& environment, uint32_t columns, uint32_t rows, uint32_t cellSize, uint32_t specularSize, uint32_t lutSize,
                            uint32_t sampleCount) {
    PreviewInputs inputs;
    inputs.specular = environmentCube(environment, specularSize, uint32_t(std::bit_width(specularSize)));
    // A cube under 4² has no mip 2: its last mip stands in (reading past the chain read whatever
    // memory followed it, and NaN now and then).
    const uint32_t chain = std::min(3u, uint32_t(std::bit_width(specularSize)));
    const auto irradianceSource = environmentCube(environment, specularSize, chain);
    const auto last = irradianceSource.mip(chain - 1);
    inputs.irradiance = {irradianceSource.mipSize(chain - 1), 1, std::vector<float>(last.begin(), last.end())};
    inputs.lutSize = lutSize;
    inputs.lut = reference::referenceBrdfLut<float>(lutSize, sampleCount);
    inputs.width = columns * cellSize;
    const uint32_t panelWidth = inputs.width / inputs.specular.mips;
    inputs.height = rows * cellSize + panelWidth / 2;
    const auto lobeTable = shading::builtLobeTable(shading::LobeWeighting::G1);
    inputs.lobeTable.assign(lobeTable.begin(), lobeTable.end());
    inputs.lights = bake::packEnvironmentLights({{glm::normalize(glm::dvec3(0.3, 0.5, 0.8)), {40, 30, 20}, 0.0086, 0.0524, 0.2}});
    const kernels::IblRecipeParameters recipe{specularSize, 0, 1.f, uint32_t(shading::LookupDirection::Fitted),
                                              uint32_t(shading::LookupLobe::Pair), 1, 2};
    inputs.parameters = {columns, rows, cellSize, inputs.specular.mips, panelWidth, 1.f, recipe};
    return inputs;
}

} // namespace iblkit::consistency
