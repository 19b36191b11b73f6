#pragma once

#include "bench_environments.hpp"
#include "bench_options.hpp"

#include <filesystem>
#include <vector>

namespace iblkit::bench {

// `iblkit batch` against separate `iblkit bake` processes (BenchOutput::Batch): every environment
// the bake can read (the built-in sky, Blender's worlds, files) as one list with the bake's default
// settings, timed as whole processes of this program in pairs (the separate bakes' walls summed,
// then the batch; the order alternating pair by pair), `options.repeat` pairs after a warm-up pair,
// once with a fresh cache per side and pair (the default bake's, found empty) and once without a
// cache. The batch's environment work is the sum of its bakes' environment-dependent steps (source
// cube, lights, irradiance, prefilter, preview). Throws BenchError where a process fails or a
// batch's folder is not byte for byte the separate bake's.
std::vector<BatchTiming> benchBatch(const BenchOptions& options, const std::vector<std::string>& environments,
                                    const std::filesystem::path& cacheDir);

} // namespace iblkit::bench
