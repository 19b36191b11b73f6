#include "shading_command.hpp"

#include "render/shading_bench.hpp"
#include "render/shading_report.hpp"
#include "signal_cleanup.hpp"

#include <fmt/core.h>

#include <memory>

namespace iblkit::cli {

void addShadingCommand(CLI::App& app) {
    struct Arguments {
        render::ShadingBenchOptions bench;
        render::ShadingReportOptions report;
        std::string cache = "bench-cache";
        bool quiet = false;
    };
    auto arguments = std::make_shared<Arguments>();
    auto& bench = arguments->bench;
    auto* command = app.add_subcommand(
        "shading", "Measure every shading recipe against the Monte Carlo reference of the split sum's BSDF and write the page");
    command->add_option("--out", arguments->report.markdown, "The page to write (docs/shading.md); its files go beside it, under shading/")
        ->required();
    command->add_option("--cache", arguments->cache,
                        "Where the references are kept and blender-data's worlds fetched to (default bench-cache)");
    command->add_option("--environments", bench.environments,
                        "sky, sun-front, sun-side, sun-behind and blender's worlds (default: all of them)")
        ->delimiter(',');
    command->add_option("--recipes", bench.recipes, "The recipes to measure (default: every one)")->delimiter(',');
    command->add_option("--cell-size", bench.cellSize, "Pixels across each sphere's cell (default 32)")->check(CLI::Range(8, 192));
    command->add_option("--device", bench.context.device, "Device index or part of its name (default: lavapipe)");
    command->add_flag("-q,--quiet", arguments->quiet, "No progress on stderr");
    command->callback([arguments] {
        files::cleanUpOnSignals();
        auto bench = arguments->bench;
        auto report = arguments->report;
        bench.cache = arguments->cache;
        bench.pictures = report.markdown.parent_path() / "shading";
        report.command = fmt::format("iblkit shading --out {} --cache {}", report.markdown.string(), arguments->cache);
        bake::BakeProgress progress(arguments->quiet);
        const auto results = render::runShadingBench(bench, progress);
        render::writeShadingReport(report, bench, results);
    });
}

} // namespace iblkit::cli
