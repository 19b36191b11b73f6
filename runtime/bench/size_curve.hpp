#pragma once

#include "bench_options.hpp"
#include "reference_cache.hpp"

#include <filesystem>
#include <vector>

namespace iblkit::vulkan {
class VulkanContext;
}

namespace iblkit::bench {

// The prefilter methods of the cost curve: the bake's default and the documents' (bake_settings.hpp
// gives each its default count).
inline constexpr const char* kSizeCurveMethods[] = {"convolution", "document"};

// The cost curve (--sizes): for each environment the bake can read (the built-in sky, Blender's
// worlds, a file), each size and each method of kSizeCurveMethods, `iblkit bake ENV --size N
// --no-cache --method M` as whole processes of this program, `options.repeat` times after a
// warm-up per method, with the median wall time and peak memory; and the method's specular error
// at its default count on that size's source cube (SpecularBench: the bench's mips and texels
// against the converged references). The synthetic "sun" and "furnace" have no file to bake and
// are left out, with a line on the log.
std::vector<SizePoint> benchSizeCurve(const BenchOptions& options, const vulkan::VulkanContext& context,
                                      const ReferenceCache& cache, const std::filesystem::path& cacheDir);

} // namespace iblkit::bench
