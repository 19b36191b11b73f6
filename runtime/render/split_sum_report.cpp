#include "render/split_sum_report.hpp"

#include "render/render_error.hpp"
#include "render/render_files.hpp"

#include "atomic_output.hpp"
#include "bake_directory.hpp"
#include "bake_error.hpp"
#include "bake_manifest.hpp"
#include "bake_outputs.hpp"
#include "bench_environments.hpp"
#include "files.hpp"
#include "scratch_folder.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <map>
#include <span>
#include <sstream>

namespace iblkit::render {
namespace {

namespace fs = std::filesystem;

struct EnvironmentRenders {
    std::string name;
    std::map<ReferenceBsdf, RenderSummary> renders;
};

std::optional<fs::path> environmentPath(const std::string& name, const fs::path& cache) {
    if (name == "sky") return std::nullopt;
    for (const char* world : bench::kBlenderWorlds)
        if (name == world) return bench::blenderWorlds(cache) / (name + ".exr");
    throw RenderError(fmt::format("no report environment '{}': sky or one of blender's worlds (forest, courtyard, ...)", name));
}

// Renders into `scratch`, then keeps its PNGs and errors.json there under the names the page uses.
RenderSummary renderInto(const fs::path& scratch, const std::optional<fs::path>& environment, ReferenceBsdf bsdf,
                         const ReportOptions& options, const std::string& toolVersion, bake::BakeProgress& progress) {
    RenderSettings settings;
    settings.environment = environment;
    settings.bsdf = bsdf;
    settings.context = options.context;
    settings.cellSize = options.cellSize;
    settings.maxSamples = options.maxSamples;
    settings.standardErrorBound = options.standardErrorBound;
    settings.outputDir = scratch / fmt::format(".render-{}", nameOf(bsdf));
    auto summary = renderSpheres(settings, toolVersion, progress);
    const auto keep = [&](const char* name, const std::string& as) { fs::rename(settings.outputDir / name, scratch / as); };
    if (bsdf == ReferenceBsdf::Document) {
        keep("reference.png", "reference.png");
        keep("splitsum.png", "splitsum.png");
    }
    keep("error.png", fmt::format("error-{}.png", nameOf(bsdf)));
    keep("errors.json", fmt::format("errors-{}.json", nameOf(bsdf)));
    fs::remove_all(settings.outputDir);
    return summary;
}

// The pictures' folder, split-sum/ beside the page.
fs::path picturesFolder(const ReportOptions& options) { return options.markdown.parent_path() / "split-sum"; }

const std::string& rowName(const SphereError& sphere) { return sphere.material; }

// One row per sphere row, one column per roughness: the mean |error|, with the sphere's summed
// (signed) error after it.
void writeTable(std::ostream& out, const RenderSummary& render) {
    const auto& grid = defaultSphereGrid();
    out << roughnessTableHead(grid, "");
    for (uint32_t row = 0; row < grid.rowCount(); ++row) {
        out << "| " << grid.rows[row].name << " |";
        for (uint32_t column = 0; column < grid.columns(); ++column) {
            const auto& sphere = render.spheres[row * grid.columns() + column];
            out << fmt::format(" {:.1f} ({:+.1f}) |", 100 * sphere.meanRelativeError, 100 * sphere.totalRelativeError);
        }
        out << "\n";
    }
}

// The spheres whose mean error against the split sum's own BSDF passes `threshold`.
std::string spheresPast(const RenderSummary& render, double threshold) {
    std::string list;
    for (const auto& sphere : render.spheres)
        if (sphere.meanRelativeError > threshold)
            list += fmt::format("{}{} at roughness {:.2g}", list.empty() ? "" : ", ", rowName(sphere), sphere.roughness);
    return list.empty() ? "none" : list;
}

void writeEnvironment(std::ostream& out, const EnvironmentRenders& environment) {
    const auto& document = environment.renders.at(ReferenceBsdf::Document);
    const auto& matched = environment.renders.at(ReferenceBsdf::SplitSum);
    out << fmt::format("## {}\n\n", environment.name);
    out << fmt::format("Reference: {:.0f} paths per pixel on average (up to {}) with the document's BSDF, {:.0f} (up to "
                       "{}) with the split sum's; every pixel's standard error within {:.2f} % and {:.2f} %.\n\n",
                       document.meanSamples, document.maxSamples, matched.meanSamples, matched.maxSamples,
                       100 * document.maxRelativeStandardError, 100 * matched.maxRelativeStandardError);
    out << fmt::format("Past 10 % from the approximation alone: {}.\n\n", spheresPast(matched, 0.1));
    out << "Against the path tracer's BSDF as ported (all of the split sum's error):\n\n";
    writeTable(out, document);
    out << "\nAgainst the same BSDF with the split sum's k and diffuse weight (the approximation alone):\n\n";
    writeTable(out, matched);
    const auto pictures = "split-sum/" + environment.name + "/";
    out << fmt::format("\n| reference (document's BSDF) | split sum | error, document's BSDF | error, split sum's BSDF |\n"
                       "|---|---|---|---|\n"
                       "| ![]({0}reference.png) | ![]({0}splitsum.png) | ![]({0}error-document.png) | "
                       "![]({0}error-split-sum.png) |\n\n",
                       pictures);
}

} // namespace

void writeSplitSumReport(const ReportOptions& options, const std::string& toolVersion, bake::BakeProgress& progress) {
    files::requireWritableFile(options.markdown, "--out");
    RenderSettings probe; // the renders' settings, refused here rather than after the first environment
    probe.outputDir = options.markdown.parent_path();
    probe.cellSize = options.cellSize;
    probe.maxSamples = options.maxSamples;
    probe.standardErrorBound = options.standardErrorBound;
    validateSettings(probe);
    const auto pictures = picturesFolder(options);
    try {
        bake::checkBakeTarget(pictures, std::nullopt, "render-report");
    } catch (const bake::BakeError& error) {
        throw RenderError(std::string("the pictures' folder: ") + error.what());
    }
    std::vector<std::optional<fs::path>> sources;
    std::vector<fs::path> inputs;
    for (const auto& name : options.environments) {
        sources.push_back(environmentPath(name, options.cache));
        if (sources.back()) inputs.push_back(*sources.back());
    }
    files::requireDistinctOutputs({options.markdown}, inputs); // the page is never one of the worlds it reads
    const files::ScratchFolder scratch("render-report");
    std::vector<EnvironmentRenders> environments;
    for (size_t i = 0; i < options.environments.size(); ++i) {
        const auto& name = options.environments[i];
        fs::create_directories(scratch.path() / name);
        EnvironmentRenders renders{name, {}};
        for (const auto bsdf : {ReferenceBsdf::Document, ReferenceBsdf::SplitSum})
            renders.renders.emplace(bsdf, renderInto(scratch.path() / name, sources[i], bsdf, options, toolVersion, progress));
        environments.push_back(std::move(renders));
    }
    std::ostringstream page;
    page << "# The split sum's error against a Monte Carlo reference\n\n"
         << fmt::format("Generated by `{}`: do not edit by hand. How the renders are made, and how to read them: "
                        "[render.md](render.md).\n\n",
                        options.command)
         << fmt::format("Each cell is one sphere of `iblkit render`'s grid: the mean over its pixels of |split sum - "
                        "reference| / reference, in percent, and in brackets the error of the sphere's summed luminance, "
                        "signed (negative: the split sum is darker). Errors are taken in luminance against max(reference, "
                        "{:g} % of the environment's mean radiance). Plastic, half-metal and gold have gold's colour (1, "
                        "0.766, 0.336) at metalness 0, 0.5 and 1; silver is (0.972, 0.960, 0.915); glass is white with eta "
                        "1.5; the first column is roughness 0.02, not 0 (runtime/render/sphere_grid.hpp). Each "
                        "environment is measured twice: against the path tracer document's BSDF as ported, and against "
                        "the same BSDF with the split sum's two choices (k = roughness² / 2 in G, the diffuse weighted by "
                        "1 - metalness alone: hlsl/Common/SplitSumMaterial.fxh), which leaves the approximation alone. "
                        "The split sum reads maps baked and shaded as the kit's recipe says ([shading-method.md](shading-method.md)). "
                        "A pixel's noise moves a sphere's mean error by at most about its standard error.\n\n",
                        100 * kRelativeFloor);
    for (const auto& environment : environments) writeEnvironment(page, environment);
    // split-sum/ is the report's own folder, replaced as a whole (as a bake's is), its manifest
    // listing every picture; the page beside it is written all or nothing, after it.
    bake::BakeDirectory directory(pictures, std::nullopt, "render-report");
    std::vector<bake::WrittenFile> written;
    for (const auto& environment : environments) {
        fs::create_directories(directory.staging() / environment.name);
        for (const auto& file : fs::directory_iterator(scratch.path() / environment.name)) {
            written.push_back(bake::writeBytes(directory.staging(), environment.name + "/" + file.path().filename().string(),
                                               image_io::readFileBytes(file.path())));
        }
    }
    const nlohmann::json manifest = {{"generator", "iblkit"}, {"command", "render-report"}, {"invocation", options.command},
                                     {"files", bake::filesJson(written)}};
    const auto manifestText = manifest.dump(2) + "\n";
    bake::writeBytes(directory.staging(), "manifest.json", std::as_bytes(std::span(manifestText.data(), manifestText.size())));
    files::AtomicOutput output;
    output.add(options.markdown, page.str());
    directory.commit();
    output.commit();
}

} // namespace iblkit::render
