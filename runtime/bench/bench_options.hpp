#pragma once

#include "kernels/kernel_table.hpp"
#include "context_options.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::bench {

enum class BenchOutput { Specular, Lut, Irradiance, Bake, Batch };
std::string_view outputName(BenchOutput output);

// The ranges validate() holds the options to (and --help states).
inline constexpr uint32_t kMinBenchCubeSize = 16, kMaxBenchCubeSize = 4096, kMaxBenchLutSize = 4096;
inline constexpr uint32_t kMaxBenchIrradianceSize = 1024, kMaxBenchRepeat = 100;

struct BenchOptions {
    std::vector<std::string> environments{"sky"}; // see bench_environments.hpp
    std::vector<std::string> methods;             // prefilter and LUT methods; empty: every one in the table
    std::vector<uint32_t> samples{16, 64, 256, 1024, 4096, 16384, 65536};
    std::vector<uint32_t> quadratureNodes{3, 4, 5, 6, 7, 8}; // the LUT quadrature's counts, nodes per panel
    std::vector<uint32_t> lutGrids{8, 16, 32, 64, 128, 192, 256};      // the LUT quadrature grid's counts, nodes per side
    std::vector<uint32_t> lutDegrees{1, 3, 5, 7, 9};         // the polynomial LUT's counts, its degree
    uint32_t size = 256;          // source cube face; specular mips down to 8x8, as the bake makes them
    std::vector<uint32_t> sizes;  // with BenchOutput::Bake, the cost curve's base sizes (size_curve.hpp), measured
                                  // instead of the cache's and the plan's bakes
    uint32_t lutSize = 512;
    uint32_t irradianceSize = 32;
    uint32_t texelsPerMip = 192;  // reference texels per specular mip, seeded
    uint32_t seamPairsPerEdge = 4; // texel pairs across each of the cube's 12 edges, per specular mip
    uint64_t seed = 1;
    uint32_t repeat = 3;          // timed runs per configuration; times are their medians
    std::vector<BenchOutput> outputs{BenchOutput::Specular, BenchOutput::Lut, BenchOutput::Irradiance};
    std::filesystem::path cacheDir; // references and downloads
    kernels::ShaderFiles shaderFiles = kernels::embeddedShaderFiles(); // what the methods compile from
    vulkan::ContextOptions context;
    std::FILE* log = stderr; // progress, one line per configuration; nullptr: quiet
};

struct MipError {
    uint32_t mip;
    double roughness;
    uint32_t texels;
    double rms, max; // luminance relative error
};

// One configuration: an output of a method at a sample count, on an environment (none for
// the LUT). Errors: specular, the worst mip's RMS and max of luminance relative error; LUT,
// absolute error of scale and bias over the whole grid; irradiance, luminance relative error
// over every texel.
struct BenchResult {
    BenchOutput output;
    std::string environment;
    std::string method;
    uint32_t samples = 0; // samples, terms per texel (convolution) or nodes per panel (LUT quadrature)
    uint32_t chunkSamples = 0; // samples per dispatch when split under the loop limit, else 0
    double deviceMilliseconds = 0; // median over the repeats
    double wallMilliseconds = 0;
    uint32_t repeat = 0;
    double errorRms = 0, errorMax = 0;
    std::vector<MipError> mips; // specular only
    // Specular only: the largest relative jump of luminance across a face edge over the mips, of the
    // result and of the converged reference at the same texels.
    double seamJump = 0, referenceSeamJump = 0;
    uint32_t halfSteps = 0; // LUT only: the furthest texel, rounded to half floats, in half steps from the converged value's nearest half
};

// A whole bake, as `iblkit bake` runs it with its default settings, timed (BenchOutput::Bake).
struct BakeTiming {
    std::string bake;        // what was baked, and with which cache: "full, no cache", "again", "scene: unlit", ...
    std::string environment;
    std::string computed;    // what the device computed: "specular mips 1-5, lut, irradiance, preview"; "nothing" when cached
    double wallMilliseconds = 0;     // the bake's own wall time, load to last file written; median over the repeats
    double fullWallMilliseconds = 0; // the same environment's full bake without a cache, the same way
    uint32_t repeat = 0;
    // Whether every value the bake's plan needs is bit for bit the full bake's, in the files both wrote.
    bool identical = true;
};

// One point of the cost curve (--sizes): a method's whole `iblkit bake` process at a base size.
struct SizePoint {
    std::string environment, method;
    uint32_t size = 0, samples = 0;
    double wallMilliseconds = 0, peakMebibytes = 0; // the process's, medians over the repeats
    uint32_t repeat = 0;
    double errorRms = 0, errorMax = 0; // the method's specular error at `samples` on that size (the worst mip's)
};

// Many default bakes as one `iblkit batch` against as many `iblkit bake` processes (BenchOutput::Batch).
struct BatchTiming {
    std::string cache;      // "fresh cache" or "no cache"
    uint32_t bakes = 0;     // the environments in the list
    double separateMilliseconds = 0; // the separate processes' walls summed; median over the pairs
    double batchMilliseconds = 0;    // the batch process's wall; median over the pairs
    double ratio = 0, ratioMin = 0, ratioMax = 0; // batch / separate, pair by pair: median, least, most
    double environmentMilliseconds = 0; // the batch's environment-dependent steps, summed; median over the pairs
    uint32_t repeat = 0;
};

struct BenchRun {
    std::string device;
    std::string machine;
    std::string date;
    std::vector<BenchResult> results;
    std::vector<BakeTiming> bakes;
    std::vector<SizePoint> sizeCurve;
    std::vector<BatchTiming> batches;
};

} // namespace iblkit::bench
