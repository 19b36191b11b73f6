#include "render_command.hpp"

#include "bake_manifest.hpp"
#include "render/render.hpp"
#include "render/render_error.hpp"
#include "render/split_sum_report.hpp"
#include "run_command.hpp"
#include "signal_cleanup.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <memory>

namespace iblkit::cli {
namespace {

nlohmann::json summaryJson(const render::RenderSummary& summary) {
    nlohmann::json spheres = nlohmann::json::array();
    for (const auto& sphere : summary.spheres)
        spheres.push_back({{"row", sphere.row}, {"column", sphere.column}, {"roughness", sphere.roughness},
                           {"metalness", sphere.metalness}, {"transmittance", sphere.transmittance},
                           {"mean_relative_error", sphere.meanRelativeError}, {"max_relative_error", sphere.maxRelativeError}});
    return {{"output", summary.outputDir.string()},
            {"device", summary.device},
            {"mean_samples_per_pixel", summary.meanSamples},
            {"max_samples_per_pixel", summary.maxSamples},
            {"max_relative_standard_error", summary.maxRelativeStandardError},
            {"wall_ms", summary.wallMilliseconds},
            {"files", bake::filesJson(summary.files)},
            {"spheres", spheres}};
}

void printSummary(const render::RenderSummary& summary, bool splitSumOnly) {
    if (splitSumOnly) {
        fmt::print(stderr, "rendered {} on {} in {:.1f} s: the split sum alone, no reference and no errors\n",
                   summary.outputDir.string(), summary.device, summary.wallMilliseconds / 1e3);
        return;
    }
    double worstMean = 0;
    for (const auto& sphere : summary.spheres) worstMean = std::max(worstMean, sphere.meanRelativeError);
    fmt::print(stderr,
               "rendered {} on {} in {:.1f} s: {:.0f} samples per pixel on average, up to {}, standard error within {:.2f} %; the split sum's "
               "mean error per sphere up to {:.1f} % (errors.json)\n",
               summary.outputDir.string(), summary.device, summary.wallMilliseconds / 1e3, summary.meanSamples, summary.maxSamples,
               100 * summary.maxRelativeStandardError, 100 * worstMean);
}

shading::ShadingRecipe recipeOption(const std::string& name) {
    try {
        return shading::recipeNamed(name);
    } catch (const std::invalid_argument& error) {
        throw render::RenderError(fmt::format("--recipe {}", error.what()));
    }
}

} // namespace

void addRenderCommand(CLI::App& app) {
    struct Arguments {
        render::RenderSettings settings;
        std::string environment, lights, bsdf = "document", recipe = shading::defaultRecipe().name;
        bool quiet = false, json = false;
    };
    auto arguments = std::make_shared<Arguments>();
    auto& s = arguments->settings;
    auto* command = app.add_subcommand(
        "render", "Render the preview's spheres by Monte Carlo with the path tracer's BSDF and by the split sum, "
                  "and measure the split sum's error");
    command->add_option("ENV", arguments->environment,
                        "Equirectangular .hdr/.exr, a folder of six faces, or a .ktx2/.dds cube (default: built-in sky)");
    command->add_option("-o,--output", s.outputDir, "Output folder (replaced as a whole when the render succeeds)")->required();
    auto* samples = command->add_option("--samples", s.maxSamples,
                                        fmt::format("Most paths per pixel for the reference, {} to {}; it stops sooner once "
                                                    "every pixel's standard error is within the bound (default {})",
                                                    render::kMinSamples, render::kMaxSamples, render::kDefaultMaxSamples));
    auto* bound = command->add_option("--max-standard-error", s.standardErrorBound,
                                      fmt::format("The reference's bound: each pixel's standard error against its value "
                                                  "(or {} % of the environment's mean radiance, if more), as a fraction, "
                                                  "{} to {} (default {})",
                                                  100 * render::kRelativeFloor, render::kMinStandardErrorBound,
                                                  render::kMaxStandardErrorBound, render::kDefaultStandardErrorBound));
    auto* lights =
        command->add_option("--lights", arguments->lights, "A JSON file of directional, point and area lights (docs/render.md)");
    auto* bsdf = command->add_option("--bsdf", arguments->bsdf,
                                     "The reference's BSDF: document (the path tracer's, as ported) or split-sum (the same "
                                     "with the split sum's k and diffuse weight, leaving only the approximation in the error)")
                     ->check(CLI::IsMember({"document", "split-sum"}));
    command->add_option("--recipe", arguments->recipe,
                        fmt::format("How the split sum's maps are made and read (docs/shading.md; default {})",
                                    shading::defaultRecipe().name));
    command->add_option("--cell-size", s.cellSize,
                        fmt::format("Pixels across each sphere's cell, {} to {} (default {})", render::kMinCellSize,
                                    render::kMaxCellSize, render::kDefaultCellSize));
    auto* seed = command->add_option("--seed", s.seed, "The reference's random seed (default 1)");
    command->add_flag("--split-sum-only", s.splitSumOnly,
                      "Render the split sum alone: splitsum.png/.exr and the grid in errors.json, no reference and no errors")
        ->excludes(samples)->excludes(bound)->excludes(lights)->excludes(bsdf)->excludes(seed);
    command->add_flag("--sanitize", s.sanitize, "Replace NaN/Inf input texels by 0 instead of refusing them");
    command->add_flag("--strict", s.strict, "Refuse negative input texels instead of clamping them to 0");
    command->add_flag("--validate", s.context.validation, "Run with the Vulkan validation layer; any message fails the render");
    command->add_option("--device", s.context.device, "Device index or part of its name (default: lavapipe)");
    command->add_flag("-q,--quiet", arguments->quiet, "No progress on stderr");
    command->add_flag("--json", arguments->json, "Print a summary with the spheres' errors as JSON");
    command->callback([arguments] {
        files::cleanUpOnSignals(); // first: the Vulkan driver's threads must inherit the blocked signals
        auto settings = arguments->settings;
        if (!arguments->environment.empty()) settings.environment = arguments->environment;
        if (!arguments->lights.empty()) settings.lights = arguments->lights;
        settings.bsdf = render::referenceBsdfNamed(arguments->bsdf);
        settings.recipe = recipeOption(arguments->recipe);
        auto log = std::make_shared<vulkan::ValidationLog>();
        settings.context.validationLog = log;
        bake::BakeProgress progress(arguments->quiet);
        const auto summary = render::renderSpheres(settings, IBLKIT_VERSION, progress);
        for (const auto& message : log->messages()) fmt::print(stderr, "validation: {}\n", message);
        if (!log->messages().empty()) throw ExpectationsFailed{};
        if (arguments->json) fmt::print("{}\n", summaryJson(summary).dump(2));
        if (!arguments->quiet) printSummary(summary, settings.splitSumOnly);
    });
}

void addRenderReportCommand(CLI::App& app) {
    struct Arguments {
        render::ReportOptions options;
        std::string cache = "bench-cache";
        std::vector<std::string> environments = render::kReportEnvironments;
        bool quiet = false;
    };
    auto arguments = std::make_shared<Arguments>();
    auto* command = app.add_subcommand(
        "render-report", "Measure the split sum's error with iblkit render on several environments and write the page");
    command->add_option("--out", arguments->options.markdown, "The page to write (docs/split-sum-error.md)")->required();
    command->add_option("--cache", arguments->cache, "Where blender-data's worlds are fetched to (default bench-cache)");
    command->add_option("--environments", arguments->environments, "sky and blender's worlds (default sky forest courtyard interior)")
        ->delimiter(',');
    auto& o = arguments->options;
    command->add_option("--cell-size", o.cellSize,
                        fmt::format("Pixels across each sphere's cell, {} to {} (default {}); smaller for a quick page",
                                    render::kMinCellSize, render::kMaxCellSize, render::kDefaultCellSize));
    command->add_option("--samples", o.maxSamples,
                        fmt::format("Most paths per pixel for each reference, {} to {} (default {})", render::kMinSamples,
                                    render::kMaxSamples, render::kDefaultMaxSamples));
    command->add_option("--max-standard-error", o.standardErrorBound,
                        fmt::format("Each reference's bound on a pixel's relative standard error, {} to {} (default {}); "
                                    "larger for a quick page",
                                    render::kMinStandardErrorBound, render::kMaxStandardErrorBound,
                                    render::kDefaultStandardErrorBound));
    command->add_option("--device", o.context.device, "Device index or part of its name (default: lavapipe)");
    command->add_flag("-q,--quiet", arguments->quiet, "No progress on stderr");
    command->callback([arguments] {
        files::cleanUpOnSignals();
        auto options = arguments->options;
        options.cache = arguments->cache;
        options.environments = arguments->environments;
        options.command = fmt::format("iblkit render-report --out {} --cache {}", options.markdown.string(), arguments->cache);
        if (arguments->environments != render::kReportEnvironments)
            options.command += " --environments " + fmt::format("{}", fmt::join(arguments->environments, ","));
        if (options.cellSize != render::kDefaultCellSize) options.command += fmt::format(" --cell-size {}", options.cellSize);
        if (options.maxSamples != render::kDefaultMaxSamples) options.command += fmt::format(" --samples {}", options.maxSamples);
        if (options.standardErrorBound != render::kDefaultStandardErrorBound)
            options.command += fmt::format(" --max-standard-error {}", options.standardErrorBound);
        bake::BakeProgress progress(arguments->quiet);
        render::writeSplitSumReport(options, IBLKIT_VERSION, progress);
    });
}

} // namespace iblkit::cli
