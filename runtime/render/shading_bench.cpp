#include "render/shading_bench.hpp"

#include "render/baked_maps.hpp"
#include "render/heat_map.hpp"
#include "render/render_error.hpp"
#include "render/render_files.hpp"
#include "render/render_settings.hpp"
#include "render/sphere_grid.hpp"
#include "render/split_sum_render.hpp"
#include "render/sun_environments.hpp"

#include "bench_environments.hpp"
#include "bake_settings.hpp"
#include "gpu_steps.hpp"
#include "float_image.hpp"
#include "kernels/kernel_table.hpp"
#include "reference_cache.hpp"
#include "sha256.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cstring>

namespace iblkit::render {
namespace {

namespace fs = std::filesystem;

bake::EnvironmentInput environmentNamed(const std::string& name, const fs::path& cache) {
    if (auto sun = sunEnvironment(name)) return std::move(*sun);
    return std::move(bench::resolveEnvironments({name}, bake::kDefaultSize, cache).front().input);
}

std::vector<const shading::ShadingRecipe*> recipesOf(const ShadingBenchOptions& options) {
    std::vector<const shading::ShadingRecipe*> recipes;
    if (options.recipes.empty())
        for (const auto& recipe : shading::benchRecipes()) recipes.push_back(&recipe);
    for (const auto& name : options.recipes) {
        try {
            recipes.push_back(&shading::recipeNamed(name));
        } catch (const std::invalid_argument& error) {
            throw RenderError(error.what());
        }
    }
    return recipes;
}

// The reference's pixels as doubles: mean RGBA, standard error RGBA and paths, per pixel; then
// its summary.
std::vector<double> flatten(const ReferenceImage& image) {
    std::vector<double> values;
    const size_t pixels = image.samples.size();
    values.reserve(pixels * 9 + 7);
    for (size_t pixel = 0; pixel < pixels; ++pixel) {
        for (size_t c = 0; c < 4; ++c) values.push_back(image.mean.rgba[4 * pixel + c]);
        for (size_t c = 0; c < 4; ++c) values.push_back(image.standardError[4 * pixel + c]);
        values.push_back(image.samples[pixel]);
    }
    values.insert(values.end(), {double(image.minSamples), double(image.maxSamples), image.meanSamples,
                                 image.maxRelativeStandardError, image.p99RelativeStandardError, image.converged ? 1.0 : 0.0,
                                 image.deviceMilliseconds});
    return values;
}

ReferenceImage unflatten(const std::vector<double>& values, uint32_t width, uint32_t height) {
    ReferenceImage image;
    const size_t pixels = size_t(width) * height;
    image.mean = {width, height, std::vector<float>(pixels * 4)};
    image.standardError.resize(pixels * 4);
    image.samples.resize(pixels);
    for (size_t pixel = 0; pixel < pixels; ++pixel) {
        const double* at = &values[pixel * 9];
        for (size_t c = 0; c < 4; ++c) image.mean.rgba[4 * pixel + c] = float(at[c]);
        for (size_t c = 0; c < 4; ++c) image.standardError[4 * pixel + c] = float(at[4 + c]);
        image.samples[pixel] = uint32_t(at[8]);
    }
    const double* summary = &values[pixels * 9];
    image.minSamples = uint32_t(summary[0]);
    image.maxSamples = uint32_t(summary[1]);
    image.meanSamples = summary[2];
    image.maxRelativeStandardError = summary[3];
    image.p99RelativeStandardError = summary[4];
    image.converged = summary[5] != 0;
    image.deviceMilliseconds = summary[6];
    return image;
}

std::string spirvHash(const kernels::KernelProgram& program) {
    return cache::sha256Hex(std::as_bytes(std::span(program.spirv)));
}

struct ReferenceRequest {
    const SphereGrid& grid;
    vulkan::Image& source;
    const SphereImage& coverage;
    ReferenceOptions options;
};

ReferenceImage cachedReference(const vulkan::VulkanContext& context, const ShadingBenchOptions& options,
                               const ReferenceRequest& request, bool& hit, bake::BakeProgress& progress) {
    const auto program = kernels::compileKernel(kernels::kernelFor(kernels::KernelRole::RenderReference, methodOf(ReferenceBsdf::SplitSum)));
    const auto packed = packSpheres(request.grid);
    const auto& o = request.options;
    const auto what = fmt::format("render reference v1: kernel {} grid {} cell {} samples {} seed {} floor {:.9g} bound {:.9g} device {}",
                                  spirvHash(program), cache::sha256Hex(std::as_bytes(std::span(packed))), o.cellSize,
                                  o.maxSamples, o.seed, o.floor, o.standardErrorBound, context.deviceInfo().name);
    const auto source = request.source.download(context);
    const auto key = bench::ReferenceCache::key(what, std::as_bytes(std::span(source)));
    const size_t count = size_t(request.coverage.width) * request.coverage.height * 9 + 7;
    const auto values = bench::ReferenceCache(options.cache).getOrCompute(
        key, count,
        [&] {
            kernels::Kernel kernel(context, program);
            return flatten(renderReference(context, kernel, request.grid, request.source, {}, request.coverage, o, progress));
        },
        &hit);
    return unflatten(values, request.coverage.width, request.coverage.height);
}

// The split sum's error against the reference, as a heat map.
void writeErrorPicture(const fs::path& file, const ReferenceImage& reference, const SphereImage& splitSum, double floor) {
    std::vector<bool> covered(size_t(splitSum.width) * splitSum.height);
    for (size_t pixel = 0; pixel < covered.size(); ++pixel) covered[pixel] = reference.mean.covered(pixel);
    const auto map = heatMap(relativeErrors(reference.mean, splitSum, floor), covered, splitSum.width, splitSum.height);
    image_io::writePng(file, map.width, map.height, map.rgba);
}

EnvironmentResult benchEnvironment(const std::string& name, const ShadingBenchOptions& options,
                                   const std::vector<const shading::ShadingRecipe*>& recipes, bake::BakeProgress& progress) {
    const auto input = environmentNamed(name, options.cache);
    const vulkan::VulkanContext context(options.context);
    auto splitSumKernel = bake::makeKernel(context, kernels::KernelRole::RenderSplitSum);
    const auto& grid = defaultSphereGrid();
    EnvironmentResult result;
    result.name = name;
    std::optional<ReferenceImage> reference;
    std::vector<glm::dvec3> exactDiffuse;
    double floor = 0;
    for (size_t i = 0; i < recipes.size(); ++i) {
        const auto started = std::chrono::steady_clock::now();
        auto maps = bakeMaps(context, input, *recipes[i], progress);
        const double bakeMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
        const auto splitSum = renderSplitSum(context, splitSumKernel, grid, maps, options.cellSize, progress);
        if (!reference) {
            floor = kRelativeFloor * std::max(meanLuminance(maps), 1e-30);
            reference = cachedReference(context, options,
                                        {grid, maps.source, splitSum,
                                         {options.cellSize, kMaxSamples, options.seed, floor, options.standardErrorBound}},
                                        result.referenceCached, progress);
            result.meanSamples = reference->meanSamples;
            result.maxSamples = reference->maxSamples;
            result.maxRelativeStandardError = reference->maxRelativeStandardError;
            result.converged = reference->converged;
            const auto folder = options.pictures / name;
            fs::create_directories(folder);
            image_io::writePng(folder / "reference.png", splitSum.width, splitSum.height,
                               toneMapped(reference->mean, exposureOf(maps)).rgba);
        }
        if (i == 0) writeErrorPicture(options.pictures / name / (recipes[i]->name + "-error.png"), *reference, splitSum, floor);
        const uint32_t irradianceSize = maps.irradiance.cube.desc().width;
        if (exactDiffuse.empty()) exactDiffuse = exactIrradiance(context, maps.source, irradianceSize, options.cache);
        const auto diffuse = irradianceError(exactDiffuse, maps.irradiance.cube.download(context), irradianceSize, maps.lights);
        result.recipes.push_back({recipes[i]->name, sphereErrors(grid, *reference, splitSum, options.cellSize, floor),
                                  maps.lights, maps.lightLevel, bakeMs, diffuse});
    }
    return result;
}

} // namespace

std::vector<std::string> defaultShadingEnvironments() {
    std::vector<std::string> names{"sky"};
    names.insert(names.end(), kSunEnvironments.begin(), kSunEnvironments.end());
    for (const char* world : bench::kBlenderWorlds) names.push_back(world);
    return names;
}

std::vector<EnvironmentResult> runShadingBench(const ShadingBenchOptions& options, bake::BakeProgress& progress) {
    const auto recipes = recipesOf(options);
    for (const auto& name : options.environments)
        if (!sunEnvironment(name)) bench::requireEnvironmentName(name);
    std::vector<EnvironmentResult> results;
    for (const auto& name : options.environments) results.push_back(benchEnvironment(name, options, recipes, progress));
    return results;
}

} // namespace iblkit::render
