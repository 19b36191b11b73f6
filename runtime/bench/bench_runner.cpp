#include "bench_runner.hpp"

#include "batch_bench.hpp"

#include "bake_bench.hpp"
#include "bench_environments.hpp"
#include "bench_error.hpp"
#include "gpu_steps.hpp"
#include "kernels/lut_methods.hpp"
#include "kernels/specular_method.hpp"
#include "measurements.hpp"
#include "size_curve.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <ctime>
#include <iterator>
#include <fstream>
#include <thread>
#include <unistd.h>

namespace iblkit::bench {
namespace {

std::string today() {
    const std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d", std::gmtime(&now));
    return text;
}

std::string machineDescription() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    while (std::getline(cpuinfo, line))
        if (line.starts_with("model name")) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    const double memory = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
    return fmt::format("{}, {} hardware threads, {:.0f} GiB", model, std::thread::hardware_concurrency(),
                       memory / double(1ull << 30));
}

bool wants(const BenchOptions& options, BenchOutput output) {
    return std::find(options.outputs.begin(), options.outputs.end(), output) != options.outputs.end();
}

struct OutputMethods {
    std::vector<std::string> lut, specular;
};

// The counts of `samples` a specular method cannot take (the convolution's budget, and a sampled
// method without a chunked twin, stop under the driver's loop limit).
std::vector<uint32_t> countsBeyond(const std::vector<uint32_t>& samples, const std::string& method) {
    std::vector<uint32_t> beyond;
    std::copy_if(samples.begin(), samples.end(), std::back_inserter(beyond),
                 [most = kernels::maxSamplesOf(method)](uint32_t count) { return count > most; });
    return beyond;
}

// The counts a LUT method is measured at: the quadrature's nodes per panel, the quadrature grid's
// nodes per side, the polynomial's degree, or the sample counts.
const std::vector<uint32_t>& lutCounts(const BenchOptions& options, const std::string& method) {
    if (method == kernels::kQuadratureGridLutMethod) return options.lutGrids;
    if (method == kernels::kFitLutMethod) return options.lutDegrees;
    return method == kernels::kQuadratureLutMethod ? options.quadratureNodes : options.samples;
}

// The LUT methods that can run at their own counts: a count past the loop limit needs the
// method's chunked twin.
std::vector<std::string> runnableLutMethods(const BenchOptions& options) {
    auto methods = kernels::lutMethods();
    const auto twins = kernels::methodsOf(kernels::KernelRole::BrdfLutChunk);
    std::erase_if(methods, [&](const std::string& method) {
        const auto& counts = lutCounts(options, method);
        const bool chunked = std::any_of(counts.begin(), counts.end(),
                                         [](uint32_t count) { return kernels::chunkSamplesFor(count) != 0; });
        return chunked && std::find(twins.begin(), twins.end(), method) == twins.end();
    });
    return methods;
}

// Each output's methods: every one the table has for it, or those asked for; a method asked for
// that has no kernel for any output the bench measures is refused before any work.
OutputMethods outputMethods(const BenchOptions& options) {
    const auto lut = runnableLutMethods(options);
    const auto specular = kernels::specularMethods();
    OutputMethods chosen;
    if (wants(options, BenchOutput::Lut)) chosen.lut = lut;
    if (wants(options, BenchOutput::Specular)) chosen.specular = specular;
    if (options.methods.empty()) return chosen;
    const auto keep = [&](std::vector<std::string>& methods) {
        std::erase_if(methods, [&](const std::string& m) {
            return std::find(options.methods.begin(), options.methods.end(), m) == options.methods.end();
        });
    };
    keep(chosen.lut);
    keep(chosen.specular);
    for (const auto& method : chosen.specular)
        if (countsBeyond(options.samples, method).size() == options.samples.size())
            throw BenchError(fmt::format("method '{}' takes at most {} samples per texel", method,
                                         kernels::maxSamplesOf(method)));
    for (const auto& method : options.methods) {
        const auto has = [&](const std::vector<std::string>& methods) {
            return std::find(methods.begin(), methods.end(), method) != methods.end();
        };
        if (!has(chosen.lut) && !has(chosen.specular))
            throw BenchError(fmt::format("method '{}' has no kernel in hlsl/shaders.json for the outputs measured at "
                                         "these sample counts (LUT: {}; specular: {})",
                                         method, fmt::join(lut, ", "), fmt::join(specular, ", ")));
    }
    return chosen;
}

OutputMethods validate(const BenchOptions& options) {
    for (const uint32_t samples : options.samples)
        if (samples == 0 || samples > kernels::kMaxSamples)
            throw BenchError(fmt::format("--samples {} is out of range: a sample count is 1 to {}", samples, kernels::kMaxSamples));
    if (options.size < kMinBenchCubeSize || options.size > kMaxBenchCubeSize || (options.size & (options.size - 1)))
        throw BenchError(fmt::format("--size {} is out of range: a power of two from {} to {}", options.size,
                                     kMinBenchCubeSize, kMaxBenchCubeSize));
    if (options.lutSize == 0 || options.lutSize > kMaxBenchLutSize)
        throw BenchError(fmt::format("--lut-size {} is out of range: 1 to {}", options.lutSize, kMaxBenchLutSize));
    for (const uint32_t nodes : options.quadratureNodes)
        if (nodes == 0 || nodes > kernels::kMaxQuadratureNodes)
            throw BenchError(fmt::format("--lut-nodes {} is out of range: the LUT quadrature takes 1 to {} nodes per panel",
                                         nodes, kernels::kMaxQuadratureNodes));
    for (const uint32_t grid : options.lutGrids)
        if (grid < kernels::kMinLutGrid || grid > kernels::kMaxLutGrid)
            throw BenchError(fmt::format("--lut-grid {} is out of range: the LUT quadrature grid takes {} to {} nodes per side",
                                         grid, kernels::kMinLutGrid, kernels::kMaxLutGrid));
    for (const uint32_t degree : options.lutDegrees)
        if (degree == 0 || degree > kernels::kMaxLutFitDegree)
            throw BenchError(fmt::format("--lut-degree {} is out of range: the polynomial LUT takes degrees 1 to {}", degree,
                                         kernels::kMaxLutFitDegree));
    for (const uint32_t size : options.sizes)
        if (size < kMinBenchCubeSize || size > kMaxBenchCubeSize || (size & (size - 1)))
            throw BenchError(fmt::format("--sizes {} is out of range: a power of two from {} to {}", size, kMinBenchCubeSize,
                                         kMaxBenchCubeSize));
    if (!options.sizes.empty() && !wants(options, BenchOutput::Bake))
        throw BenchError("--sizes measures whole bakes: give --outputs bake");
    if (options.repeat == 0 || options.repeat > kMaxBenchRepeat)
        throw BenchError(fmt::format("--repeat {} is out of range: 1 to {}", options.repeat, kMaxBenchRepeat));
    if (options.texelsPerMip == 0) throw BenchError("--texels 0 is out of range: the reference needs at least one texel per mip");
    if (options.irradianceSize == 0 || options.irradianceSize > kMaxBenchIrradianceSize)
        throw BenchError(fmt::format("--irradiance-size {} is out of range: 1 to {}", options.irradianceSize,
                                     kMaxBenchIrradianceSize));
    return outputMethods(options);
}

void logSpecularLimits(const BenchOptions& options, const std::vector<std::string>& methods) {
    if (!options.log) return;
    for (const auto& method : methods)
        if (const auto beyond = countsBeyond(options.samples, method); !beyond.empty())
            fmt::print(options.log, "bench  {}: {} above its limit of {}, not measured\n", method, fmt::join(beyond, ", "),
                       kernels::maxSamplesOf(method));
}

void logResult(const BenchOptions& options, const BenchResult& result) {
    if (!options.log) return;
    const bool relative = result.output != BenchOutput::Lut;
    const auto error = [&](double value) {
        return relative ? fmt::format("{:.3g} %", 100 * value) : fmt::format("{:.2e}", value);
    };
    fmt::print(options.log, "bench  {:<10} {:<11} {:<10} {:>7} samples  RMS {:>10}  max {:>10}  device {:8.1f} ms  wall {:8.1f} ms\n",
               outputName(result.output), result.environment.empty() ? "-" : result.environment, result.method,
               result.samples, error(result.errorRms), error(result.errorMax), result.deviceMilliseconds,
               result.wallMilliseconds);
    std::fflush(options.log);
}

void benchEnvironment(const vulkan::VulkanContext& context, const BenchEnvironment& environment,
                      const std::vector<std::string>& methods, const BenchOptions& options, const ReferenceCache& cache,
                      std::vector<BenchResult>& results) {
    bake::BakeProgress quiet(true);
    auto source = bake::buildSourceCube(context, environment.input, options.size, quiet);
    const reference::MippedCube cube{options.size, source.desc().mips, source.download(context)};
    const auto add = [&](BenchResult result) {
        result.environment = environment.name;
        logResult(options, result);
        results.push_back(std::move(result));
    };
    if (wants(options, BenchOutput::Specular)) {
        if (options.log) fmt::print(options.log, "bench  {}: converged prefilter references\n", environment.name);
        SpecularBench specular(context, source, cube, options, cache);
        for (const auto& method : methods)
            for (const uint32_t samples : options.samples)
                if (samples <= kernels::maxSamplesOf(method)) add(specular.measure(method, samples));
    }
    if (wants(options, BenchOutput::Irradiance)) add(measureIrradiance(context, source, cube, options, cache));
}

} // namespace

std::string_view outputName(BenchOutput output) {
    switch (output) {
    case BenchOutput::Specular: return "specular";
    case BenchOutput::Lut: return "lut";
    case BenchOutput::Irradiance: return "irradiance";
    case BenchOutput::Bake: return "bake";
    case BenchOutput::Batch: return "batch";
    }
    return "?";
}

BenchRun runBench(const BenchOptions& options) {
    const auto methods = validate(options);
    const auto cacheDir = options.cacheDir.empty() ? ReferenceCache::defaultFolder() : options.cacheDir;
    const ReferenceCache cache(cacheDir);
    const auto environments = resolveEnvironments(options.environments, options.size, cacheDir);
    logSpecularLimits(options, methods.specular);
    // Whole bakes first, while no other device is open.
    // With --sizes the whole bakes are the cost curve's, measured after the rest.
    auto bakes = wants(options, BenchOutput::Bake) && options.sizes.empty() ? benchBakes(options, environments, cacheDir)
                                                                             : std::vector<BakeTiming>{};
    std::vector<std::string> names;
    for (const auto& environment : environments) names.push_back(environment.name);
    auto batches = wants(options, BenchOutput::Batch) ? benchBatch(options, names, cacheDir) : std::vector<BatchTiming>{};
    const vulkan::VulkanContext context(options.context);
    BenchRun run{context.deviceInfo().name, machineDescription(), today(), {}, std::move(bakes), {}, std::move(batches)};
    if (wants(options, BenchOutput::Lut)) {
        if (options.log) fmt::print(options.log, "bench  converged LUT reference ({}²)\n", options.lutSize);
        LutBench lut(context, options, cache);
        for (const auto& method : methods.lut)
            for (const uint32_t samples : lutCounts(options, method)) {
                run.results.push_back(lut.measure(method, samples));
                logResult(options, run.results.back());
            }
    }
    for (const auto& environment : environments)
        benchEnvironment(context, environment, methods.specular, options, cache, run.results);
    if (!options.sizes.empty()) run.sizeCurve = benchSizeCurve(options, context, cache, cacheDir);
    return run;
}

} // namespace iblkit::bench
