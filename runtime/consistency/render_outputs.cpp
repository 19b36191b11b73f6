#include "render_outputs.hpp"

#include "gl_cube_bake.hpp"
#include "gpu_cube_bake.hpp"
#include "gl_support.hpp"
#include "consistency_suite.hpp"
#include "suite_inputs.hpp"

#include "kernels/kernel.hpp"
#include "kernels/kernel_steps.hpp"
#include "render/environment_distribution.hpp"
#include "render/lights_file.hpp"
#include "render/sphere_grid.hpp"
#include "shading/shading_recipe.hpp"
#include "shading/transmission_table.hpp"
#include "shading_maps.hpp"

#include <fmt/core.h>

namespace iblkit::consistency {
namespace {

constexpr uint32_t kCellSize = 8, kSamples = 16, kSeed = 3;

const render::SphereGrid& grid() { return render::defaultSphereGrid(); }

uint32_t gridWidth() { return grid().columns() * kCellSize; }
uint32_t gridHeight() { return grid().rowCount() * kCellSize; }

} // namespace

const std::vector<float>& sphereMaterials() {
    static const auto materials = render::packSpheres(grid());
    return materials;
}

namespace {

// What RenderReferenceCS reads: the environment with its distribution at mip 0, and the lights.
struct ReferenceInputs {
    MippedCube environment;
    std::vector<float> cdf;
    std::vector<float> lights;
    std::vector<uint32_t> pixels; // every pixel active
    kernels::RenderReferenceParameters parameters;
    uint32_t width, height;
};

ReferenceInputs referenceInputs(const SuiteOptions& options) {
    ReferenceInputs inputs;
    inputs.environment = environmentCube(options.environment, options.cubeSize, uint32_t(std::bit_width(options.cubeSize)));
    const auto mip0 = inputs.environment.mip(0);
    inputs.cdf = render::environmentCdf({mip0.begin(), mip0.end()}, options.cubeSize);
    using render::RenderLight;
    inputs.lights = render::packLights({{RenderLight::Kind::Directional, {-0.3f, -0.5f, -0.81f}, {}, {}, {3, 2, 1}},
                                        {RenderLight::Kind::Point, {2, 3, 4}, {}, {}, {40, 40, 40}},
                                        {RenderLight::Kind::Area, {-1, 2, 2}, {2, 0, 0}, {0, 0, 1}, {5, 5, 5}}});
    inputs.width = gridWidth();
    inputs.height = gridHeight();
    for (uint32_t pixel = 0; pixel < inputs.width * inputs.height; ++pixel) inputs.pixels.push_back(pixel);
    inputs.parameters = {grid().columns(), kCellSize, 0, kSamples, kSeed, 3, options.cubeSize, 0,
                         uint32_t(inputs.pixels.size())};
    return inputs;
}

// The radiance sums, then the sums of squares.
std::vector<float> gpuReference(const vulkan::VulkanContext& context, const PathProgram& program, const ReferenceInputs& inputs) {
    kernels::Kernel kernel(context, program);
    vulkan::Image environment(context, {"Environment", &vulkan::rgba32Float(), inputs.environment.size, inputs.environment.size, 6,
                                        inputs.environment.mips, false, false});
    environment.upload(context, inputs.environment.texels);
    const auto cdf = vulkan::storageBuffer(context, std::as_bytes(std::span(inputs.cdf)), "EnvironmentCdf");
    const auto lights = vulkan::storageBuffer(context, std::as_bytes(std::span(inputs.lights)), "Lights");
    const auto pixels = vulkan::storageBuffer(context, std::as_bytes(std::span(inputs.pixels)), "ActivePixels");
    const auto spheres = vulkan::storageBuffer(context, std::as_bytes(std::span(sphereMaterials())), "Spheres");
    vulkan::Image sums(context, {"RadianceSum", &vulkan::rgba32Float(), inputs.width, inputs.height, 1, 1, false, true});
    vulkan::Image squares(context, {"SquareSum", &vulkan::rgba32Float(), inputs.width, inputs.height, 1, 1, false, true});
    const std::vector<float> zeros(sums.valueCount(), 0.f);
    sums.upload(context, zeros);
    squares.upload(context, zeros);
    kernels::runRenderReference(kernel, {spheres, environment, cdf, lights, pixels, sums, squares}, inputs.parameters);
    auto values = sums.download(context);
    const auto more = squares.download(context);
    values.insert(values.end(), more.begin(), more.end());
    return values;
}

std::vector<float> glReference(const opengl::EglContext& context, const OpenGlForm& form, const ReferenceInputs& inputs) {
    const auto program = glpath::program(context, form);
    const auto& cube = inputs.environment;
    const auto environment = glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, cube.size, cube.mips, cube.texels);
    glpath::bindTexture(context, form, "Environment", environment);
    const auto cdfBytes = std::as_bytes(std::span(inputs.cdf));
    const auto cdf = glpath::bindStorageBuffer(context, form, "EnvironmentCdf", cdfBytes.size(), cdfBytes);
    const auto lightBytes = std::as_bytes(std::span(inputs.lights));
    const auto lights = glpath::bindStorageBuffer(context, form, "Lights", lightBytes.size(), lightBytes);
    const auto pixelBytes = std::as_bytes(std::span(inputs.pixels));
    const auto pixels = glpath::bindStorageBuffer(context, form, "ActivePixels", pixelBytes.size(), pixelBytes);
    const auto sphereBytes = std::as_bytes(std::span(sphereMaterials()));
    const auto spheres = glpath::bindStorageBuffer(context, form, "Spheres", sphereBytes.size(), sphereBytes);
    const std::vector<float> zeros(size_t(inputs.width) * inputs.height * 4, 0.f);
    const auto sums = glpath::texture2D(context, GL_RGBA32F, GL_RGBA, inputs.width, inputs.height, zeros);
    const auto squares = glpath::texture2D(context, GL_RGBA32F, GL_RGBA, inputs.width, inputs.height, zeros);
    context.gl().BindImageTexture(glpath::slotOf(form, "RadianceSum"), sums.name(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    context.gl().BindImageTexture(glpath::slotOf(form, "SquareSum"), squares.name(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    const auto parameters = glpath::bindParameters(context, form, inputs.parameters.members());
    glpath::dispatch(context, program, form, {uint32_t(inputs.pixels.size()), 1, 1});
    auto values = glpath::readTexture(context, sums, 0, GL_RGBA, zeros.size());
    const auto more = glpath::readTexture(context, squares, 0, GL_RGBA, zeros.size());
    values.insert(values.end(), more.begin(), more.end());
    return values;
}

} // namespace

kernels::RenderSplitSumParameters splitSumParameters(const PreviewInputs& maps) {
    const auto& glass = shading::defaultRecipe().glass;
    return {grid().columns(), kCellSize, maps.specular.mips, maps.parameters.recipe, uint32_t(glass.transmission),
            float(glass.roughnessScale)};
}

std::vector<float> gpuSplitSum(const vulkan::VulkanContext& context, const PathProgram& program, const PreviewInputs& inputs) {
    kernels::Kernel kernel(context, program);
    auto maps = uploadShadingMaps(context, inputs);
    const vulkan::Sampler linear(context, {});
    vulkan::Image image(context, {"SplitSum", &vulkan::rgba32Float(), gridWidth(), gridHeight(), 1, 1, false, true});
    const auto spheres = vulkan::storageBuffer(context, std::as_bytes(std::span(sphereMaterials())), "Spheres");
    auto glass = bake::glassTables(context, shading::defaultRecipe().glass.transmission);
    kernels::runRenderSplitSum(kernel, {spheres, maps.specular, maps.irradiance, maps.lut, maps.lobeTable, glass.transmission,
                                        glass.sphere, maps.lights, linear, image},
                               splitSumParameters(inputs));
    return image.download(context);
}

PreviewInputs splitSumMaps(const SuiteOptions& options) {
    return previewInputs(options.environment, 1, 1, 1, options.cubeSize, options.chunkLutSize, options.sampleCount);
}

namespace {

std::vector<float> glSplitSum(const opengl::EglContext& context, const OpenGlForm& form, const PreviewInputs& inputs) {
    const auto program = glpath::program(context, form);
    const auto maps = bindShadingMaps(context, form, inputs);
    const uint32_t width = gridWidth(), height = gridHeight();
    const auto sphereBytes = std::as_bytes(std::span(sphereMaterials()));
    const auto spheres = glpath::bindStorageBuffer(context, form, "Spheres", sphereBytes.size(), sphereBytes);
    const auto glassTransmission = shading::defaultRecipe().glass.transmission;
    const auto layers = uint32_t(shading::kTransmissionEtas.size());
    const uint32_t interfaceSize = bake::transmissionTableSize(glassTransmission);
    const uint32_t sphereSize = bake::sphereTransmissionTableSize(glassTransmission);
    const auto transmissionTable = glpath::texture2D(context, GL_RG32F, GL_RG, interfaceSize, interfaceSize * layers,
                                                     bake::transmissionTableOf(interfaceSize));
    const auto sphereTable = glpath::texture2D(context, GL_RGBA32F, GL_RGBA, sphereSize, sphereSize * layers,
                                               bake::sphereTransmissionTableOf(sphereSize));
    // Each table is read through the sampler and, for its size, alone (GetDimensions).
    for (const auto& [name, texture] : {std::pair{"TransmissionTable", &transmissionTable},
                                        std::pair{"SphereTransmissionTable", &sphereTable}}) {
        const std::string sampled = std::string(name) + "+LinearClamp";
        glpath::bindTexture(context, form, sampled, *texture);
        context.gl().BindSampler(glpath::slotOf(form, sampled), maps.sampler.name());
        glpath::bindTexture(context, form, name, *texture);
    }
    const auto image = glpath::texture2D(context, GL_RGBA32F, GL_RGBA, width, height);
    context.gl().BindImageTexture(glpath::slotOf(form, "SplitSum"), image.name(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    const auto bound = glpath::bindParameters(context, form, splitSumParameters(inputs).members());
    glpath::dispatch(context, program, form, {width, height, 1});
    return glpath::readTexture(context, image, 0, GL_RGBA, size_t(width) * height * 4);
}

} // namespace

void addRenderOutputs(SuiteRun& run) {
    if (!run.runs("RenderReferenceCS") && !run.runs("RenderReferenceSplitSumMaterialCS") && !run.runs("SplitSumSpheresCS"))
        return;
    const auto& options = run.options;
    const auto reference = referenceInputs(options);
    const auto output = fmt::format("{}×{} spheres, {} paths a pixel, radiance and square sums", reference.width,
                                    reference.height, kSamples);
    for (const char* kernel : {"RenderReferenceCS", "RenderReferenceSplitSumMaterialCS"})
        addOutputAgainstPathA(run, {kernel, output, renderReferenceBounds()},
                              [&](const PathProgram& program) { return gpuReference(run.vulkan, program, reference); },
                              [&](const OpenGlForm& form) { return glReference(run.gl, form, reference); });
    const auto maps = splitSumMaps(options);
    addOutputAgainstPathA(run, {"SplitSumSpheresCS", fmt::format("{}×{} spheres, fitted pairs of lookups and a light", reference.width, reference.height),
                                splitSumSpheresBounds()},
                          [&](const PathProgram& program) { return gpuSplitSum(run.vulkan, program, maps); },
                          [&](const OpenGlForm& form) { return glSplitSum(run.gl, form, maps); });
}

} // namespace iblkit::consistency
