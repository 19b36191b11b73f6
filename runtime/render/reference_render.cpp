#include "render/reference_render.hpp"

#include "render/environment_distribution.hpp"
#include "render/render_error.hpp"
#include "render/render_settings.hpp"

#include "buffer.hpp"
#include "gpu_steps.hpp"
#include "kernels/kernel_steps.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace iblkit::render {
namespace {

constexpr uint32_t kDistributionLimit = 256;

struct Distribution {
    std::vector<float> cdf;
    uint32_t faceSize, mip;
};

Distribution distributionOf(const vulkan::VulkanContext& context, const vulkan::Image& environment) {
    const uint32_t mip = bake::firstMipAtMost(environment.desc().width, kDistributionLimit);
    const uint32_t size = environment.mipWidth(mip);
    const auto values = environment.download(context);
    const auto first = values.begin() + std::ptrdiff_t(environment.valueOffset(mip, 0));
    const std::vector<float> faces(first, first + std::ptrdiff_t(size_t(6) * size * size * 4));
    return {environmentCdf(faces, size), size, mip};
}

struct Accumulators {
    vulkan::Image radiance, squares;
    Accumulators(const vulkan::VulkanContext& context, uint32_t width, uint32_t height)
        : radiance(context, {"RadianceSum", &vulkan::texelFormatNamed("R32G32B32A32_SFLOAT"), width, height, 1, 1, false, true}),
          squares(context, {"SquareSum", &vulkan::texelFormatNamed("R32G32B32A32_SFLOAT"), width, height, 1, 1, false, true}) {
        const std::vector<float> zeros(radiance.valueCount(), 0.f);
        radiance.upload(context, zeros);
        squares.upload(context, zeros);
    }
};

std::span<const float> rgbAt(const std::vector<float>& rgba, size_t pixel) { return std::span(rgba).subspan(4 * pixel, 3); }

// The mean and standard error of each of `pixels` from its sums over its own count of paths (the
// other pixels' sums have not moved).
void estimate(ReferenceImage& image, const std::vector<uint32_t>& pixels, const std::vector<float>& sums,
              const std::vector<float>& squares) {
    for (const uint32_t pixel : pixels) {
        const double n = image.samples[pixel];
        for (size_t c = 0; c < 3; ++c) {
            const double mean = sums[4 * pixel + c] / n;
            const double variance = std::max(squares[4 * pixel + c] / n - mean * mean, 0.0) * n / (n - 1);
            image.mean.rgba[4 * pixel + c] = float(mean);
            image.standardError[4 * pixel + c] = float(std::sqrt(variance / n));
        }
    }
}

double relativeStandardError(const ReferenceImage& image, size_t pixel, double floor) {
    return luminance(rgbAt(image.standardError, pixel)) / relativeTo(luminance(rgbAt(image.mean.rgba, pixel)), floor);
}

// The pixels to go on with: not yet within the bound, or short of kMinSamples, and short of the most.
std::vector<uint32_t> stillActive(const ReferenceImage& image, const std::vector<uint32_t>& active, const ReferenceOptions& options) {
    std::vector<uint32_t> next;
    for (const uint32_t pixel : active) {
        const uint32_t n = image.samples[pixel];
        if (n >= options.maxSamples) continue;
        if (n < kMinSamples || relativeStandardError(image, pixel, options.floor) > options.standardErrorBound) next.push_back(pixel);
    }
    return next;
}

void summarize(ReferenceImage& image, const ReferenceOptions& options) {
    std::vector<double> relative;
    double total = 0;
    image.minSamples = ~0u;
    for (size_t pixel = 0; pixel < image.samples.size(); ++pixel) {
        if (!image.samples[pixel]) continue;
        relative.push_back(relativeStandardError(image, pixel, options.floor));
        image.minSamples = std::min(image.minSamples, image.samples[pixel]);
        image.maxSamples = std::max(image.maxSamples, image.samples[pixel]);
        total += image.samples[pixel];
    }
    if (relative.empty()) {
        image.minSamples = 0;
        image.converged = true;
        return;
    }
    image.meanSamples = total / double(relative.size());
    std::sort(relative.begin(), relative.end());
    image.maxRelativeStandardError = relative.back();
    image.p99RelativeStandardError = relative[size_t(0.99 * double(relative.size() - 1))];
    image.converged = image.maxRelativeStandardError <= options.standardErrorBound;
}

// kBatchSamples paths a pixel while most pixels are active, then as many more as keep each batch's
// work about the same, in powers of 2.
uint32_t batchSamples(size_t covered, size_t active) {
    uint32_t samples = kBatchSamples;
    while (samples < kMaxBatchSamples && size_t(samples) * 2 * active <= size_t(kBatchSamples) * covered) samples *= 2;
    return samples;
}

// Every pixel traced as many paths as it was dispatched: the shader counts them in the radiance
// sum's alpha.
void requireEveryPath(const ReferenceImage& image, const std::vector<uint32_t>& active, const std::vector<float>& sums) {
    for (const uint32_t pixel : active) {
        const float ran = sums[4 * pixel + 3];
        if (ran != float(image.samples[pixel]))
            throw RenderError(fmt::format("the device ended the reference's loops early: pixel {} traced {} of {} paths "
                                          "(a loop iteration budget per invocation; see docs/render.md)",
                                          pixel, ran, image.samples[pixel]));
    }
}

} // namespace

uint32_t pathsWithinLoopBudget(uint32_t distributionSize, size_t lightCount) {
    constexpr uint64_t kLoopBudget = 65535, kVertices = 4;
    // The environment draw's binary search takes ceil(log2(texels)) steps; each loop's entry may
    // cost one iteration more than its trips: the depth loop's, and per vertex the search's and
    // three over the lights (their terms, whether one hides the environment's draw, and what the
    // BSDF's draw meets when it leaves).
    const uint64_t searchSteps = std::bit_width(uint64_t(6) * distributionSize * distributionSize - 1);
    const uint64_t perVertex = 1 + (searchSteps + 1) + 3 * (lightCount + 1);
    const uint64_t perPath = 2 + kVertices * perVertex;
    return uint32_t(std::bit_floor(std::clamp<uint64_t>(kLoopBudget / perPath, 1, kMaxBatchSamples)));
}

ReferenceImage renderReference(const vulkan::VulkanContext& context, kernels::Kernel& kernel, const SphereGrid& grid,
                               vulkan::Image& environment, const std::vector<RenderLight>& lights, const SphereImage& coverage,
                               const ReferenceOptions& options, bake::BakeProgress& progress) {
    progress.begin("reference");
    const auto distribution = distributionOf(context, environment);
    const auto cdf = vulkan::storageBuffer(context, std::as_bytes(std::span(distribution.cdf)), "EnvironmentCdf");
    const auto lightValues = packLights(lights);
    const auto lightBuffer = vulkan::storageBuffer(context, std::as_bytes(std::span(lightValues)), "Lights");
    const auto materials = packSpheres(grid);
    const auto spheres = vulkan::storageBuffer(context, std::as_bytes(std::span(materials)), "Spheres");
    Accumulators sums(context, coverage.width, coverage.height);
    const size_t pixels = size_t(coverage.width) * coverage.height;
    ReferenceImage image;
    image.mean = {coverage.width, coverage.height, std::vector<float>(pixels * 4, 0.f)};
    image.standardError.assign(pixels * 4, 0.f);
    image.samples.assign(pixels, 0);
    std::vector<uint32_t> active;
    for (size_t pixel = 0; pixel < pixels; ++pixel)
        if (coverage.covered(pixel)) {
            active.push_back(uint32_t(pixel));
            image.mean.rgba[4 * pixel + 3] = 1.f;
        }
    const size_t covered = active.size();
    kernels::RenderReferenceParameters parameters{grid.columns(), options.cellSize, 0, 0, options.seed,
                                                  uint32_t(lights.size()), distribution.faceSize, distribution.mip, 0};
    const uint32_t perDispatch =
        options.pathsPerDispatch ? options.pathsPerDispatch : pathsWithinLoopBudget(distribution.faceSize, lights.size());
    uint32_t batch = 0;
    for (uint32_t done = 0; !active.empty(); done += batch) {
        const auto activeBuffer = vulkan::storageBuffer(context, std::as_bytes(std::span(active)), "ActivePixels");
        batch = std::min(batchSamples(covered, active.size()), options.maxSamples - done);
        parameters.activeCount = uint32_t(active.size());
        for (uint32_t part = 0; part < batch; part += perDispatch) {
            parameters.firstSample = done + part;
            parameters.sampleCount = std::min(perDispatch, batch - part);
            kernels::runRenderReference(kernel, {spheres, environment, cdf, lightBuffer, activeBuffer, sums.radiance, sums.squares},
                                        parameters);
        }
        for (const uint32_t pixel : active) image.samples[pixel] += batch;
        const auto radiance = sums.radiance.download(context);
        requireEveryPath(image, active, radiance);
        estimate(image, active, radiance, sums.squares.download(context));
        active = stillActive(image, active, options);
        progress.advance(1.0 - double(active.size()) / double(covered),
                         fmt::format("{} paths, {} pixels to go", done + batch, active.size()));
    }
    summarize(image, options);
    image.deviceMilliseconds = kernel.takeTotals().deviceMilliseconds;
    progress.addDeviceTime(image.deviceMilliseconds);
    progress.end();
    return image;
}

} // namespace iblkit::render
