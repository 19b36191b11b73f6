#include "render/render.hpp"

#include "render/baked_maps.hpp"
#include "render/render_error.hpp"
#include "render/render_files.hpp"
#include "render/split_sum_render.hpp"

#include "bake_directory.hpp"
#include "bake_manifest.hpp"
#include "baked_outputs.hpp"
#include "environment_input.hpp"
#include "file_names.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <optional>

namespace iblkit::render {
namespace {

void writeManifest(const std::filesystem::path& folder, const std::string& toolVersion,
                   std::vector<bake::WrittenFile> files) {
    const nlohmann::json manifest = {{"generator", "iblkit"}, {"version", toolVersion}, {"command", "render"}, {"kind", "render"},
                                     {"files", bake::filesJson(files)}};
    writeText(folder / "manifest.json", manifest.dump(2) + "\n");
}

std::string environmentName(const RenderSettings& settings) {
    return settings.environment ? image_io::utf8Name(settings.environment->filename()) : "built-in sky";
}

void requireConverged(const ReferenceImage& reference, const RenderSettings& settings) {
    if (reference.converged) return;
    // More samples cannot help a sum that overflowed: the environment (or a light) is too bright.
    if (!std::isfinite(reference.maxRelativeStandardError))
        throw RenderError("the reference's float sums overflowed: a pixel's value or standard error is not finite, the "
                          "environment being too bright for them (its brightest texels, squared, pass the float range); "
                          "scale it down");
    throw RenderError(fmt::format("the reference did not converge in {} samples per pixel: a pixel's standard error is "
                                  "{:.2f} % of its value, past the {:.2f} % bound (raise --samples or --max-standard-error)",
                                  settings.maxSamples, 100 * reference.maxRelativeStandardError,
                                  100 * settings.standardErrorBound));
}

// The Monte Carlo reference of the grid, refused unless it converged.
ReferenceImage convergedReference(const vulkan::VulkanContext& context, const SphereGrid& grid, BakedMaps& maps,
                                  const std::vector<RenderLight>& lights, const SphereImage& splitSum,
                                  const RenderSettings& settings, double floor, bake::BakeProgress& progress) {
    kernels::Kernel kernel(
        context, kernels::compileKernel(kernels::kernelFor(kernels::KernelRole::RenderReference, methodOf(settings.bsdf))));
    auto reference = renderReference(context, kernel, grid, maps.source, lights, splitSum,
                                     {settings.cellSize, settings.maxSamples, settings.seed, floor, settings.standardErrorBound},
                                     progress);
    requireConverged(reference, settings);
    return reference;
}

} // namespace

RenderSummary renderSpheres(const RenderSettings& settings, const std::string& toolVersion, bake::BakeProgress& progress) {
    const auto started = std::chrono::steady_clock::now();
    validateSettings(settings);
    const auto lights = settings.lights ? readLightsFile(*settings.lights) : std::vector<RenderLight>{};
    bake::BakeDirectory directory(settings.outputDir, settings.environment, "render");
    const auto input = bake::loadEnvironment(settings.environment, {settings.sanitize, settings.strict, "render"});
    const vulkan::VulkanContext context(settings.context);
    auto maps = bakeMaps(context, input, settings.recipe, progress);
    auto splitSumKernel = bake::makeKernel(context, kernels::KernelRole::RenderSplitSum);
    const auto& grid = defaultSphereGrid();
    const auto splitSum = renderSplitSum(context, splitSumKernel, grid, maps, settings.cellSize, progress);
    const double floor = kRelativeFloor * std::max(meanLuminance(maps), 1e-30);
    RenderSummary summary;
    RenderReport report{environmentName(settings), settings.bsdf, settings.recipe.name, &grid, settings.cellSize, floor,
                        settings.standardErrorBound, exposureOf(maps)};
    std::optional<ReferenceImage> reference;
    if (!settings.splitSumOnly) {
        reference = convergedReference(context, grid, maps, lights, splitSum, settings, floor, progress);
        summary.spheres = sphereErrors(grid, *reference, splitSum, settings.cellSize, floor);
        summary.meanSamples = reference->meanSamples;
        summary.maxSamples = reference->maxSamples;
        summary.maxRelativeStandardError = reference->maxRelativeStandardError;
        report.reference = &*reference;
        report.spheres = &summary.spheres;
    }
    summary.files = writeRenderFiles(directory.staging(), report, splitSum);
    writeManifest(directory.staging(), toolVersion, summary.files);
    directory.commit();
    summary.outputDir = settings.outputDir;
    summary.device = context.deviceInfo().name;
    summary.wallMilliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    return summary;
}

} // namespace iblkit::render
