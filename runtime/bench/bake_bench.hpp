#pragma once

#include "bench_environments.hpp"
#include "bench_options.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::bench {

// Whole bakes with the bake's default settings, as `iblkit bake` runs them (bakeEnvironment in this
// process), each timed `options.repeat` times: the built-in sky's first bake with empty caches
// (the kit's and Mesa's shader cache), its first with an empty cache of the kit's alone, its full
// bake without a cache, the same bake again; then every Blender world among `environments`
// (blender-data's files under `cacheDir`) in a row on that cache, each beside its own full bake;
// then the sky for each bench scene (bench_scenes.hpp), without a cache. Each bake's files are
// compared with its environment's full bake wherever its plan needs values. Throws BenchError, or
// the bake's errors.
std::vector<BakeTiming> benchBakes(const BenchOptions& options, const std::vector<BenchEnvironment>& environments,
                                   const std::filesystem::path& cacheDir);

// Whether each level of the KTX2 file `name` in the folder `baked` that `needed` marks (every level
// past its end) holds the bytes of the same file in `full`; true when `baked` has no such file.
bool neededLevelsMatch(const std::filesystem::path& full, const std::filesystem::path& baked, const std::string& name,
                       const std::vector<bool>& needed);

} // namespace iblkit::bench
