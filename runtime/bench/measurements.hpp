#pragma once

#include "bench_options.hpp"
#include "reference_cache.hpp"

#include "image.hpp"
#include "mipped_cube.hpp"

#include <glm/vec3.hpp>

#include <chrono>
#include <span>
#include <vector>

namespace iblkit::bench {

// Times `run` `repeat` times; the medians of the device time it returns and of its wall time.
struct Timing {
    double deviceMilliseconds, wallMilliseconds;
};
template <typename Run>
Timing timeRepeated(uint32_t repeat, const Run& run);

double median(std::vector<double> values);

// The RMS and the largest of a run of errors; a NaN counts as an infinite error.
class ErrorSummary {
public:
    void add(double error);
    double rms() const;
    double max() const { return max_; }

private:
    double sumSquares_ = 0, max_ = 0;
    size_t count_ = 0;
};

// RGB values as the reference cache stores them, and back.
std::vector<double> flatten(const std::vector<glm::dvec3>& rgb);
std::vector<glm::dvec3> unflatten(const std::vector<double>& values);

double luminance(glm::dvec3 rgb);
// |actual - reference| / reference in luminance; 0 when both are 0.
double relativeLuminanceError(glm::dvec3 actual, glm::dvec3 reference);


// Prefilter methods over every specular mip >= 1 of a source cube, against the converged
// prefilter at the seeded texels of each mip.
class SpecularBench {
public:
    SpecularBench(const vulkan::VulkanContext& context, vulkan::Image& source, const reference::MippedCube& cube,
                  const BenchOptions& options, const ReferenceCache& cache);
    ~SpecularBench();
    BenchResult measure(const std::string& method, uint32_t samples);

private:
    struct MipReference;
    const vulkan::VulkanContext& context_;
    vulkan::Image& source_;
    const BenchOptions& options_;
    uint32_t mips_;
    std::vector<MipReference> references_;
};

// LUT methods over the whole grid against the converged quadrature.
class LutBench {
public:
    LutBench(const vulkan::VulkanContext& context, const BenchOptions& options, const ReferenceCache& cache);
    BenchResult measure(const std::string& method, uint32_t samples);

private:
    const vulkan::VulkanContext& context_;
    const BenchOptions& options_;
    std::vector<double> reference_;
};

// The bake's irradiance steps against the exact sum over the source cube.
BenchResult measureIrradiance(const vulkan::VulkanContext& context, vulkan::Image& source, const reference::MippedCube& cube,
                              const BenchOptions& options, const ReferenceCache& cache);

template <typename Run>
Timing timeRepeated(uint32_t repeat, const Run& run) {
    std::vector<double> device, wall;
    for (uint32_t i = 0; i < repeat; ++i) {
        const auto started = std::chrono::steady_clock::now();
        device.push_back(run());
        wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count());
    }
    return {median(device), median(wall)};
}

} // namespace iblkit::bench
