#include "bench_command.hpp"

#include "bench_report.hpp"
#include "bench_runner.hpp"
#include "kernels/sampled_methods.hpp"
#include "shell_command.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <memory>

namespace iblkit::cli {
namespace {

std::vector<bench::BenchOutput> parseOutputs(const std::vector<std::string>& names) {
    std::vector<bench::BenchOutput> outputs;
    for (const auto& name : names)
        for (const auto output : {bench::BenchOutput::Specular, bench::BenchOutput::Lut, bench::BenchOutput::Irradiance,
                                  bench::BenchOutput::Bake, bench::BenchOutput::Batch})
            if (bench::outputName(output) == name) outputs.push_back(output);
    return outputs;
}

// A word of the command as a shell reads it back.
std::string word(const std::string& text) {
    const bool plain = !text.empty() && text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                               "0123456789-_./,=+:") == std::string::npos;
    return plain ? text : bench::shellQuoted(text);
}

// The command as a user would type it again, for the report.
std::string invocation(const bench::BenchOptions& options, const std::vector<std::string>& outputs,
                       const std::string& out, const std::string& markdown) {
    std::string text = "iblkit bench";
    for (const auto& environment : options.environments) text += " " + word(environment);
    if (!options.methods.empty()) text += fmt::format(" --method {}", word(fmt::format("{}", fmt::join(options.methods, ","))));
    text += fmt::format(" --samples {} --lut-nodes {} --lut-grid {} --lut-degree {} --size {} --lut-size {} "
                        "--irradiance-size {} --texels {} --seed {} --repeat {} --outputs {}",
                        fmt::join(options.samples, ","), fmt::join(options.quadratureNodes, ","),
                        fmt::join(options.lutGrids, ","), fmt::join(options.lutDegrees, ","), options.size,
                        options.lutSize, options.irradianceSize,
                        options.texelsPerMip, options.seed, options.repeat, fmt::join(outputs, ","));
    if (!options.sizes.empty()) text += fmt::format(" --sizes {}", fmt::join(options.sizes, ","));
    if (!options.context.device.empty()) text += " --device " + word(options.context.device);
    text += " --out " + word(out);
    if (!markdown.empty()) text += " --markdown " + word(markdown);
    return text;
}

} // namespace

void addBenchCommand(CLI::App& app) {
    struct Arguments {
        bench::BenchOptions options;
        std::vector<std::string> outputs{"specular", "lut", "irradiance"};
        std::string out, markdown, cache;
        bool quiet = false;
    };
    auto arguments = std::make_shared<Arguments>();
    auto& o = arguments->options;
    auto* command = app.add_subcommand("bench", "Measure run time against error for every method and sample count, "
                                                "against converged references");
    command->add_option("ENV", o.environments,
                        "sky (default), furnace, sun, blender (its eight world HDRIs), one of them by name (forest, ...), "
                        "or an .hdr/.exr/.ktx2/.dds file or a folder of faces");
    command->add_option("--method", o.methods, "Methods from hlsl/shaders.json (default: every one)")->delimiter(',');
    command->add_option("--samples", o.samples,
                        fmt::format("Sample counts, each 1 to {} (default 16,64,256,1024,4096,16384,65536)", kernels::kMaxSamples))
        ->delimiter(',');
    command->add_option("--lut-nodes", o.quadratureNodes,
                        "The LUT quadrature's Gauss-Legendre nodes per panel, 1 to 16 (default 3,4,5,6,7,8)")
        ->delimiter(',');
    command->add_option("--lut-grid", o.lutGrids,
                        "The LUT quadrature grid's nodes per side, 4 to 1024 (default 8,16,32,64,128,192,256)")
        ->delimiter(',');
    command->add_option("--lut-degree", o.lutDegrees, "The polynomial LUT's degrees, 1 to 9 (default 1,3,5,7,9)")
        ->delimiter(',');
    command->add_option("--size", o.size,
                        fmt::format("Source cube face size, a power of two from {} to {} (default 256)", bench::kMinBenchCubeSize,
                                    bench::kMaxBenchCubeSize));
    command->add_option("--sizes", o.sizes,
                        fmt::format("With --outputs bake, the cost curve instead of the cache's and the plan's bakes: "
                                    "whole bakes at these base sizes (powers of two from {} to {}), the default method's and "
                                    "the documents', with their time, peak memory and specular error",
                                    bench::kMinBenchCubeSize, bench::kMaxBenchCubeSize))
        ->delimiter(',');
    command->add_option("--lut-size", o.lutSize, fmt::format("BRDF LUT size, 1 to {} (default 512)", bench::kMaxBenchLutSize));
    command->add_option("--irradiance-size", o.irradianceSize,
                        fmt::format("Irradiance cube face size, 1 to {} (default 32)", bench::kMaxBenchIrradianceSize));
    command->add_option("--texels", o.texelsPerMip, "Reference texels per specular mip, 1 or more (default 192)");
    command->add_option("--seed", o.seed, "Seed of the reference texels, any whole number from 0 (default 1)");
    command->add_option("--repeat", o.repeat,
                        fmt::format("Timed runs per configuration, 1 to {}; times are medians (default 3)", bench::kMaxBenchRepeat));
    command->add_option("--outputs", arguments->outputs,
                        "What to measure (default specular,lut,irradiance; bake: whole default bakes, with and "
                        "without the cache, and the bench's scenes; batch: the environments as one iblkit batch against separate "
                        "iblkit bake processes)")
        ->delimiter(',')
        ->check(CLI::IsMember({"specular", "lut", "irradiance", "bake", "batch"}));
    command->add_option("--cache", arguments->cache, "Folder for converged references and downloads "
                                                     "(default $XDG_CACHE_HOME/iblkit or ~/.cache/iblkit)");
    command->add_option("--out", arguments->out, "Folder for results.csv, results.json and the plots")->required();
    command->add_option("--markdown", arguments->markdown, "Also write the report (e.g. docs/bench.md)");
    command->add_option("--device", o.context.device, "Device index or part of its name (default: lavapipe)");
    command->add_flag("-q,--quiet", arguments->quiet, "No progress on stderr");
    command->callback([arguments] {
        auto options = arguments->options;
        options.outputs = parseOutputs(arguments->outputs);
        options.cacheDir = arguments->cache;
        if (arguments->quiet) options.log = nullptr;
        bench::checkResultsWritable(arguments->out, arguments->markdown, options.environments);
        const auto run = bench::runBench(options);
        const auto command = invocation(options, arguments->outputs, arguments->out, arguments->markdown);
        const auto plots = bench::writeBenchResults(run, command, arguments->out, arguments->markdown);
        if (!arguments->quiet)
            fmt::print(stderr, "wrote {} results, {} plots to {}\n", run.results.size(), plots.size(), arguments->out);
    });
}

} // namespace iblkit::cli
