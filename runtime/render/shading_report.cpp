#include "render/shading_report.hpp"

#include "render/render_error.hpp"
#include "render/render_files.hpp"
#include "render/render_settings.hpp"
#include "render/sphere_grid.hpp"

#include "profiles/engine_profile.hpp"

#include "embedded_tools.hpp"
#include "shell_command.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace iblkit::render {
namespace {

namespace fs = std::filesystem;

constexpr const char* kPython = "/usr/bin/python3";
constexpr double kNoiseShare = 0.8; // E|n| / σ for a normal n

// A value to six decimal places, as results.json keeps it.
double rounded(double value) { return std::round(value * 1e6) / 1e6; }

nlohmann::json column(const std::vector<SphereError>& spheres, double SphereError::*field) {
    nlohmann::json values = nlohmann::json::array();
    for (const auto& sphere : spheres) values.push_back(rounded(sphere.*field));
    return values;
}

// The grid once, then per environment and recipe one array per measure, sphere by sphere in the
// grid's order (row after row).
nlohmann::json resultsJson(const std::vector<EnvironmentResult>& results) {
    const auto& grid = defaultSphereGrid();
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& row : grid.rows) rows.push_back(row.name);
    nlohmann::json environments = nlohmann::json::array();
    for (const auto& environment : results) {
        nlohmann::json recipes = nlohmann::json::array();
        for (const auto& recipe : environment.recipes) {
            nlohmann::json lights = nlohmann::json::array();
            for (const auto& light : recipe.lights)
                lights.push_back({{"direction", {light.direction.x, light.direction.y, light.direction.z}},
                                  {"radiance", {light.radiance.r, light.radiance.g, light.radiance.b}},
                                  {"solid_angle", light.solidAngle},
                                  {"angular_radius", light.angularRadius},
                                  {"share", light.share}});
            recipes.push_back({{"recipe", recipe.recipe},
                               {"light_level", recipe.lightLevel},
                               {"lights", lights},
                               {"bake_ms", rounded(recipe.bakeMilliseconds)},
                               {"irradiance_rms_relative_error", rounded(recipe.irradiance.rms)},
                               {"irradiance_max_relative_error", rounded(recipe.irradiance.max)},
                               {"mean_relative_error", column(recipe.spheres, &SphereError::meanRelativeError)},
                               {"max_relative_error", column(recipe.spheres, &SphereError::maxRelativeError)},
                               {"total_relative_error", column(recipe.spheres, &SphereError::totalRelativeError)},
                               {"mean_relative_standard_error", column(recipe.spheres, &SphereError::meanRelativeStandardError)}});
        }
        environments.push_back({{"name", environment.name},
                                {"reference", {{"mean_samples", environment.meanSamples},
                                               {"max_samples", environment.maxSamples},
                                               {"max_relative_standard_error", environment.maxRelativeStandardError},
                                               {"converged", environment.converged}}},
                                {"recipes", recipes}});
    }
    return {{"generator", "iblkit shading"},
            {"grid", {{"roughness", grid.roughness}, {"rows", rows}}},
            {"environments", environments}};
}

// The plots of results.json into `folder`, as tools/shading_plot.py draws them.
void drawPlots(const fs::path& resultsJson, const fs::path& folder) {
    const std::string command = fmt::format("{} - {} {} > /dev/null", kPython, bench::shellQuoted(resultsJson.string()),
                                            bench::shellQuoted(folder.string()));
    if (bench::runWithInput(command, bench::embeddedBenchTools().at("tools/shading_plot.py")) != 0)
        throw RenderError("tools/shading_plot.py could not draw the plots (see its message above)");
}

std::string percent(double value) { return fmt::format("{:.1f}", 100 * value); }

struct Worst {
    double value = -1;
    std::string where;
    void take(double candidate, const std::string& at) {
        if (candidate > value) value = candidate, where = at;
    }
};

// Sums below a roughness this low are decided by whether a pixel's centre finds a light's
// reflection (shading-method.md), so the summary also gives the worst from it on.
constexpr float kLotteryRoughness = 0.2f;

struct RecipeSummary {
    size_t opaque = 0, met = 0;
    double excessSum = 0;
    Worst excess, total, roughTotal, glass, irradiance;
    double bakeMs = 0;
};

std::map<std::string, RecipeSummary> summarize(const std::vector<EnvironmentResult>& results) {
    std::map<std::string, RecipeSummary> summaries;
    for (const auto& environment : results)
        for (const auto& recipe : environment.recipes) {
            auto& summary = summaries[recipe.recipe];
            summary.bakeMs = std::max(summary.bakeMs, recipe.bakeMilliseconds);
            summary.irradiance.take(recipe.irradiance.max, environment.name);
            for (const auto& sphere : recipe.spheres) {
                const auto at = fmt::format("{} {:g} on {}", sphere.material, sphere.roughness, environment.name);
                if (sphere.transmittance > 0) {
                    summary.glass.take(sphere.meanRelativeError, at);
                    continue;
                }
                ++summary.opaque;
                summary.met += meetsTarget(sphere) ? 1 : 0;
                summary.excess.take(excessError(sphere), at);
                summary.excessSum += excessError(sphere);
                summary.total.take(std::abs(sphere.totalRelativeError), at);
                if (sphere.roughness >= kLotteryRoughness) summary.roughTotal.take(std::abs(sphere.totalRelativeError), at);
            }
        }
    return summaries;
}

std::string describe(const shading::ShadingRecipe& recipe) {
    std::string text = fmt::format("{} lobe, {} lods{}, {} direction, {} lookup", recipe.weighting == shading::LobeWeighting::G1 ? "G1" : "N·L",
                                   shading::nameOf(recipe.mapping),
                                   recipe.mapping == shading::LodMapping::Power || recipe.mapping == shading::LodMapping::Logarithmic
                                       ? fmt::format(" ({:g})", recipe.mappingParameter)
                                       : "",
                                   shading::nameOf(recipe.direction), shading::nameOf(recipe.lookup));
    if (recipe.lights)
        text += fmt::format(", lights above {:g}× the mean carrying {:g} % within {:.1f}°", recipe.lights->threshold,
                            100 * recipe.lights->minShare, recipe.lights->maxRadius * 180 / 3.14159265358979);
    text += fmt::format(", glass: {} transmission", shading::nameOf(recipe.glass.transmission));
    if (recipe.glass.transmission != shading::GlassTransmission::Sphere && recipe.glass.roughnessScale != 1)
        text += fmt::format(" at {:g}× the roughness", recipe.glass.roughnessScale);
    return text;
}

void writeSummary(std::ostream& out, const std::vector<EnvironmentResult>& results) {
    const auto summaries = summarize(results);
    out << fmt::format("| recipe | how | opaque spheres within both targets | their mean error above noise, on average | "
                       "the worst | worst summed error | worst from roughness {:g} | worst glass mean error | worst irradiance "
                       "error | slowest bake |\n"
                       "|---|---|---:|---:|---|---|---|---|---|---:|\n",
                       kLotteryRoughness);
    for (const auto& recipe : results.front().recipes) {
        const auto& s = summaries.at(recipe.recipe);
        out << fmt::format("| {} | {} | {} of {} | {} % | {} % ({}) | {} % ({}) | {} % ({}) | {} % ({}) | {:.2f} % ({}) | "
                           "{:.2f} s |\n",
                           recipe.recipe, describe(shading::recipeNamed(recipe.recipe)), s.met, s.opaque,
                           percent(s.excessSum / double(std::max<size_t>(s.opaque, 1))), percent(s.excess.value),
                           s.excess.where, percent(s.total.value), s.total.where, percent(s.roughTotal.value),
                           s.roughTotal.where, percent(s.glass.value), s.glass.where, 100 * s.irradiance.value,
                           s.irradiance.where, s.bakeMs / 1e3);
    }
}

// One row per engine profile whose recipe the bench measured: that recipe's row, named by the engine.
void writeEngineTable(std::ostream& out, const std::vector<EnvironmentResult>& results) {
    const auto summaries = summarize(results);
    out << fmt::format("| profile | engine | recipe | opaque spheres within both targets | their mean error above noise, on "
                       "average | the worst | worst summed from roughness {:g} |\n|---|---|---|---:|---:|---|---|\n",
                       kLotteryRoughness);
    for (const auto& profile : profiles::engineProfiles()) {
        const auto found = summaries.find(std::string(profile.recipe));
        if (found == summaries.end()) continue;
        const auto& s = found->second;
        out << fmt::format("| `{}` | {} | {} | {} of {} | {} % | {} % ({}) | {} % ({}) |\n", profile.name, profile.engine,
                           profile.recipe, s.met, s.opaque, percent(s.excessSum / double(std::max<size_t>(s.opaque, 1))),
                           percent(s.excess.value), s.excess.where, percent(s.roughTotal.value), s.roughTotal.where);
    }
}

// The diffuse's source against the exact sum, per environment, for each recipe that takes
// out other lights than the recipes before it (the rest read the same irradiance).
void writeIrradianceTable(std::ostream& out, const std::vector<EnvironmentResult>& results) {
    std::vector<size_t> shown;
    std::vector<std::string> kinds;
    const auto& recipes = results.front().recipes;
    for (size_t i = 0; i < recipes.size(); ++i) {
        const auto& recipe = shading::recipeNamed(recipes[i].recipe);
        const auto kind = recipe.lights ? fmt::format("{} {} {} {} {}", recipe.lights->threshold, recipe.lights->minShare,
                                                      recipe.lights->maxRadius, recipe.lights->maxLights, recipe.irradianceSource)
                                        : fmt::format("none {}", recipe.irradianceSource);
        if (std::find(kinds.begin(), kinds.end(), kind) != kinds.end()) continue;
        kinds.push_back(kind);
        shown.push_back(i);
    }
    out << "| environment |";
    for (const size_t i : shown) out << " " << recipes[i].recipe << " |";
    out << "\n|---|";
    for (size_t i = 0; i < shown.size(); ++i) out << "---:|";
    out << "\n";
    for (const auto& environment : results) {
        out << "| " << environment.name << " |";
        for (const size_t i : shown) {
            const auto& error = environment.recipes[i].irradiance;
            const bool met = error.max <= kIrradianceTarget;
            out << fmt::format(" {}{:.2f} % / {:.2f} %{} |", met ? "" : "**", 100 * error.rms, 100 * error.max, met ? "" : "**");
        }
        out << "\n";
    }
}

// Per sphere of the grid: the recipe whose worst excess over the environments is least.
void writeFrontier(std::ostream& out, const std::vector<EnvironmentResult>& results) {
    const auto& grid = defaultSphereGrid();
    std::map<std::pair<std::string, size_t>, double> worst; // (recipe, sphere) -> worst over environments
    for (const auto& environment : results)
        for (const auto& recipe : environment.recipes)
            for (size_t i = 0; i < recipe.spheres.size(); ++i) {
                const auto& sphere = recipe.spheres[i];
                const double error = sphere.transmittance > 0 ? sphere.meanRelativeError : excessError(sphere);
                auto& value = worst[{recipe.recipe, i}];
                value = std::max(value, error);
            }
    out << roughnessTableHead(grid, "");
    for (uint32_t row = 0; row < grid.rowCount(); ++row) {
        out << "| " << grid.rows[row].name << " |";
        for (uint32_t column = 0; column < grid.columns(); ++column) {
            const size_t i = size_t(row) * grid.columns() + column;
            std::string best;
            double bestError = 1e30;
            for (const auto& recipe : results.front().recipes)
                if (const double error = worst.at({recipe.recipe, i}); error < bestError) bestError = error, best = recipe.recipe;
            out << fmt::format(" {} {} |", percent(bestError), best);
        }
        out << "\n";
    }
}

// Rows of recipes, columns of roughness: one material's mean error per pixel, with its summed error.
void writeMaterialTable(std::ostream& out, const EnvironmentResult& environment, const std::string& material) {
    const auto& grid = defaultSphereGrid();
    out << roughnessTableHead(grid, material);
    for (const auto& recipe : environment.recipes) {
        out << "| " << recipe.recipe << " |";
        for (const auto& sphere : recipe.spheres)
            if (sphere.material == material)
                out << fmt::format(" {} ({:+.1f}) |", percent(sphere.meanRelativeError), 100 * sphere.totalRelativeError);
        out << "\n";
    }
}

// Every sphere of one recipe: mean error per pixel (summed error), the noise's mean share below.
void writeGridTable(std::ostream& out, const RecipeResult& recipe) {
    const auto& grid = defaultSphereGrid();
    out << roughnessTableHead(grid, "");
    for (uint32_t row = 0; row < grid.rowCount(); ++row) {
        out << "| " << grid.rows[row].name << " |";
        for (uint32_t column = 0; column < grid.columns(); ++column) {
            const auto& sphere = recipe.spheres[size_t(row) * grid.columns() + column];
            const bool met = sphere.transmittance > 0 ? sphere.meanRelativeError <= kGlassTarget : meetsTarget(sphere);
            out << fmt::format(" {}{} ({:+.1f}) ±{}{} |", met ? "" : "**", percent(sphere.meanRelativeError),
                               100 * sphere.totalRelativeError, percent(kNoiseShare * sphere.meanRelativeStandardError),
                               met ? "" : "**");
        }
        out << "\n";
    }
}

void writeLights(std::ostream& out, const RecipeResult& recipe) {
    if (recipe.lights.empty()) {
        out << "The default recipe takes no light out of this environment.\n\n";
        return;
    }
    out << fmt::format("The default recipe takes out {} light{} (the maps keep them below mip {}):", recipe.lights.size(),
                       recipe.lights.size() == 1 ? "" : "s", recipe.lightLevel);
    for (const auto& light : recipe.lights)
        out << fmt::format(" {:.1f} % of the light within {:.2f}°;", 100 * light.share, light.angularRadius * 180 / 3.14159265358979);
    out << "\n\n";
}

void writeEnvironment(std::ostream& out, const EnvironmentResult& environment, const std::string& pictures) {
    out << fmt::format("### {}\n\n", environment.name);
    out << fmt::format("Reference: {:.0f} paths per pixel on average, up to {}; {}every pixel's standard error within "
                       "{:.2f} %{}.\n\n",
                       environment.meanSamples, environment.maxSamples, environment.converged ? "" : "**not converged**: ",
                       100 * environment.maxRelativeStandardError, environment.referenceCached ? " (from the cache)" : "");
    writeLights(out, environment.recipes.front());
    for (const char* metal : {"gold", "silver"}) {
        writeMaterialTable(out, environment, metal);
        out << "\n";
    }
    out << fmt::format("Every sphere with the default recipe ({}): mean error per pixel (summed error) ± the noise's "
                       "share of the mean; in bold past the target.\n\n",
                       environment.recipes.front().recipe);
    writeGridTable(out, environment.recipes.front());
    const auto folder = pictures + "/" + environment.name + "/";
    out << fmt::format("\n| reference | {0}, error |\n|---|---|\n| ![]({1}reference.png) | ![]({1}{0}-error.png) |\n\n"
                       "![]({2}{3}.png)\n\n",
                       environment.recipes[0].recipe, folder, pictures + "/", environment.name);
}

} // namespace

double excessError(const SphereError& sphere) {
    return std::max(sphere.meanRelativeError - kNoiseShare * sphere.meanRelativeStandardError, 0.0);
}

bool meetsTarget(const SphereError& sphere) {
    return excessError(sphere) <= kMeanTarget && std::abs(sphere.totalRelativeError) <= kTotalTarget;
}

void writeShadingReport(const ShadingReportOptions& options, const ShadingBenchOptions& bench,
                        const std::vector<EnvironmentResult>& results) {
    if (results.empty() || results.front().recipes.empty()) throw RenderError("the shading bench measured nothing");
    const auto folder = options.markdown.parent_path() / "shading";
    fs::create_directories(folder);
    writeText(folder / "results.json", resultsJson(results).dump() + "\n");
    drawPlots(folder / "results.json", folder);
    std::ostringstream page;
    page << "# Shading: the split sum against its Monte Carlo truth\n\n"
         << fmt::format("Generated by `{}`: do not edit by hand. How it is measured, and what the recipes are: "
                        "[shading-method.md](shading-method.md).\n\n",
                        options.command)
         << fmt::format("Each environment is rendered by Monte Carlo with the split sum's own BSDF (`iblkit render --bsdf "
                        "split-sum`: k = r² / 2, diffuse × (1 − metalness)), every pixel's standard error within {:g} % of "
                        "its value, at {}-pixel cells; then each recipe bakes the environment at the bake's defaults and "
                        "shades the same pixels. A sphere's mean error is the mean over its pixels of |split sum − "
                        "reference| / max(reference, {:g} % of the environment's mean radiance), in luminance; its summed "
                        "error is its summed luminance's, signed. The targets: every opaque sphere's mean error no more "
                        "than {:g} % above the reference's own noise (0.8 of its mean relative standard error) and its "
                        "summed error within ±{:g} %; glass's mean error within {:g} %.\n\n",
                        100 * bench.standardErrorBound, bench.cellSize, 100 * kRelativeFloor, 100 * kMeanTarget,
                        100 * kTotalTarget, 100 * kGlassTarget)
         << "## Every recipe, over every environment\n\n";
    writeSummary(page, results);
    page << "\n## Per engine\n\nEach engine profile's shading against the Monte Carlo truth when it reads the maps its "
            "profile bakes (`iblkit bake --profile`): its recipe's row above, which reads the chain the profile writes, by "
            "the engine's lod mapping and direction, one lookup at the surface's roughness, and the lights the bake takes "
            "out as the engine's own lights. The engine's own DFG table and multiple scattering are not in it: "
            "[engines.md](engines.md) measures, in a browser, how far each engine's picture departs from this split sum.\n\n";
    writeEngineTable(page, results);
    page << "\n![](shading/summary.png)\n\n## The best recipe per sphere\n\nThe worst over the environments of each "
            "sphere's mean error above noise (glass: its mean error), for the recipe with the least.\n\n";
    writeFrontier(page, results);
    page << fmt::format("\n## Irradiance against the exact sum\n\nWhat the diffuse reads — the irradiance map (the "
                        "moments of the source's 32² mip summed, of the environment without its lights where the recipe "
                        "takes them out, plus the lights' texels' exact irradiance less their caps') plus each light's "
                        "E / π as IblDiskLight adds it (the exact cosine integral of its cap) — "
                        "against the exact integral over the source cube's texels (Lambert's formula where a normal's "
                        "horizon cuts one), at every texel of the 32² map: RMS / max relative error of "
                        "luminance, in bold past the target ({:g} % everywhere). One column per way of taking lights "
                        "out; the other recipes read the same.\n\n",
                        100 * kIrradianceTarget);
    writeIrradianceTable(page, results);
    page << "\n## Environment by environment\n\n";
    for (const auto& environment : results) writeEnvironment(page, environment, "shading");
    writeText(options.markdown, page.str());
}

} // namespace iblkit::render
