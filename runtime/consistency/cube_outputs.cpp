// The kit's cube kernels: the panorama's resampling, the mip chain, the harmonics, the
// irradiance cube and the preview.
#include "gl_cube_bake.hpp"
#include "gpu_cube_bake.hpp"
#include "reference_bake.hpp"
#include "reference_irradiance.hpp"
#include "sky_environment.hpp"
#include "suite_run.hpp"

#include <fmt/core.h>

#include <bit>
#include <numbers>

namespace iblkit::consistency {
namespace {

// The 9 coefficients' RGB, then the solid angle the texels covered.
std::vector<float> flattened(const std::array<glm::dvec3, 9>& radiance, double solidAngle) {
    std::vector<float> values;
    for (const auto& coefficient : radiance)
        values.insert(values.end(), {float(coefficient.r), float(coefficient.g), float(coefficient.b)});
    values.push_back(float(solidAngle));
    return values;
}

std::vector<double> flattenedInDouble(const std::array<glm::dvec3, 9>& radiance, double solidAngle) {
    std::vector<double> values;
    for (const auto& coefficient : radiance) values.insert(values.end(), {coefficient.r, coefficient.g, coefficient.b});
    values.push_back(solidAngle);
    return values;
}

std::vector<double> rgbaWithAlphaOne(const std::vector<glm::dvec3>& texels) {
    std::vector<double> values;
    for (const auto& texel : texels) values.insert(values.end(), {texel.r, texel.g, texel.b, 1.0});
    return values;
}

void addSkyOutput(SuiteRun& run) {
    const uint32_t size = run.options.cubeSize, supersample = run.options.supersample;
    addOutput(run, {"SkyCubeCS", fmt::format("built-in environment → {}², {}² evaluations", size, supersample), skyBounds()},
              [&] { return References{reference::skyCube<float>(size, supersample), reference::skyCube<double>(size, supersample)}; },
              [&](const PathProgram& program) { return gpuSkyCube(run.vulkan, program, size, supersample); },
              [&](const OpenGlForm& form) { return glSkyCube(run.gl, form, size, supersample); });
}

void addEquirectOutput(SuiteRun& run) {
    const auto& options = run.options;
    const auto panorama = options.environment.panorama(options.panoramaWidth);
    const uint32_t size = options.cubeSize, supersample = options.supersample;
    const auto reference = [&]<typename T>(T) {
        return reference::referenceEquirectToCube<T>(panorama.texels, panorama.width, panorama.height, size, supersample);
    };
    const auto output = fmt::format("panorama {}×{} → {}², {}² reads", panorama.width, panorama.height, size, supersample);
    addOutput(run, {"EquirectToCubeCS", output, equirectBounds()},
              [&] { return References{reference(0.f), reference(0.0)}; },
              [&](const PathProgram& program) { return gpuEquirectToCube(run.vulkan, program, panorama, size, supersample); },
              [&](const OpenGlForm& form) { return glEquirectToCube(run.gl, form, panorama, size, supersample); });
}

// Each mip of the double reference is reference::downsampleCube of the one above.
void addDownsampleOutput(SuiteRun& run, const MippedCube& cube) {
    if (!run.runs("DownsampleCubeCS")) return;
    References references;
    std::vector<float> level(cube.mip(0).begin(), cube.mip(0).end());
    for (uint32_t mip = 1; mip < cube.mips; ++mip) {
        const auto inFloat = cube.mip(mip);
        references.inFloat.insert(references.inFloat.end(), inFloat.begin(), inFloat.end());
        level = reference::downsampleCube(level, cube.mipSize(mip - 1));
        references.inDouble.insert(references.inDouble.end(), level.begin(), level.end());
    }
    addOutput(run, {"DownsampleCubeCS", fmt::format("mips 1–{} of {}²", cube.mips - 1, cube.size), downsampleBounds()},
              [&] { return references; }, [&](const PathProgram& program) { return gpuDownsampleChain(run.vulkan, program, cube); },
              [&](const OpenGlForm& form) { return glDownsampleChain(run.gl, form, cube); });
}

void addShOutput(SuiteRun& run, const MippedCube& cube, uint32_t mip) {
    const auto source = cube.mip(mip);
    const std::vector<float> texels(source.begin(), source.end());
    const auto inFloat = reference::projectOnShInFloat(texels, cube.mipSize(mip));
    const auto output = fmt::format("SH of mip {} ({}²): 27 coefficients, solid angle", mip, cube.mipSize(mip));
    addOutput(run, {"ShProjectCS", output, shBounds()},
              [&] { return References{flattened(inFloat.radiance, inFloat.solidAngle),
               flattenedInDouble(reference::projectOnSh(texels, cube.mipSize(mip)), 4 * std::numbers::pi)}; },
              [&](const PathProgram& program) {
                  const auto projection = gpuShProject(run.vulkan, program, cube, mip);
                  return flattened(projection.radiance, projection.solidAngle);
              },
              [&](const OpenGlForm& form) {
                  const auto projection = glShProject(run.gl, form, cube, mip);
                  return flattened(projection.radiance, projection.solidAngle);
              });
}

// The moments of mip `mip`, each summed from its texels of the mip above (a 1² cube's from itself).
void addIrradianceOutput(SuiteRun& run, const MippedCube& cube, uint32_t mip) {
    if (!run.runs("IrradianceCubeCS")) return;
    const uint32_t fineMip = mip > 0 ? mip - 1 : 0;
    const auto source = cube.mip(fineMip);
    const uint32_t size = cube.mipSize(mip), outSize = run.options.irradianceSize;
    const auto moments = reference::irradianceMoments({source.begin(), source.end()}, cube.mipSize(fineMip), size);
    const auto output = fmt::format("irradiance {}² from the moments of mip {} ({}²)", outSize, mip, size);
    addOutput(run, {"IrradianceCubeCS", output, irradianceBounds()},
              [&] { return References{reference::irradianceCubeInFloat(moments, size, outSize),
               rgbaWithAlphaOne(reference::irradianceFromMoments(moments, size, outSize))}; },
              [&](const PathProgram& program) { return gpuIrradianceCube(run.vulkan, program, moments, size, outSize); },
              [&](const OpenGlForm& form) { return glIrradianceCube(run.gl, form, moments, size, outSize); });
}

} // namespace

void addSkyOutputs(SuiteRun& run) { addSkyOutput(run); }

void addCubeOutputs(SuiteRun& run) {
    addEquirectOutput(run);
    const uint32_t size = run.options.mipChainSize;
    const auto cube = environmentCube(run.options.environment, size, uint32_t(std::bit_width(size)));
    addDownsampleOutput(run, cube);
    const uint32_t mip = std::min(1u, cube.mips - 1); // a 1² cube has no mip 1
    addShOutput(run, cube, mip);
    addIrradianceOutput(run, cube, mip);
}

// No C++ reference (see boundsRationale): the paths are compared with path a.
void addPreviewOutput(SuiteRun& run) {
    if (!run.runs("PreviewCS")) return;
    const auto& options = run.options;
    const auto inputs = previewInputs(options.environment, options.previewColumns, options.previewRows, options.previewCellSize, options.cubeSize,
                                      options.chunkLutSize, options.sampleCount);
    addOutputAgainstPathA(run, {"PreviewCS", fmt::format("preview {}×{}", inputs.width, inputs.height), previewBounds()},
                          [&](const PathProgram& program) { return gpuPreview(run.vulkan, program, inputs); },
                          [&](const OpenGlForm& form) { return glPreview(run.gl, form, inputs); });
}

} // namespace iblkit::consistency
