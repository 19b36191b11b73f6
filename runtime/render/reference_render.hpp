#pragma once

#include "render/lights_file.hpp"
#include "render/sphere_grid.hpp"
#include "render/sphere_images.hpp"

#include "bake_progress.hpp"
#include "image.hpp"
#include "kernels/kernel.hpp"

namespace iblkit::render {

struct ReferenceOptions {
    uint32_t cellSize = 0;
    uint32_t maxSamples = 0;  // paths per pixel at the most
    uint32_t seed = 0;
    double floor = 0;         // luminance below which relative errors are taken against this
    double standardErrorBound = 0;
    uint32_t pathsPerDispatch = 0; // 0: as many as llvmpipe's loop budget allows (pathsWithinLoopBudget)
};

struct ReferenceImage {
    SphereImage mean;                 // the Monte Carlo estimate, alpha the coverage
    std::vector<float> standardError; // of the mean, RGB per pixel (alpha 0)
    std::vector<uint32_t> samples;    // paths per pixel (0 outside the spheres)
    uint32_t minSamples = 0, maxSamples = 0; // over the spheres' pixels
    double meanSamples = 0;
    // Over covered pixels: the standard error of the luminance (taking the channels' errors as
    // fully correlated, which bounds it) against max(luminance, floor).
    double maxRelativeStandardError = 0;
    double p99RelativeStandardError = 0;
    bool converged = false;
    double deviceMilliseconds = 0;
};

// The most paths a pixel one dispatch of RenderReferenceCS can trace, in a power of 2. llvmpipe
// counts every iteration of every loop of one invocation against a single budget of 65535 (Mesa's
// gallivm loop limiter, one counter per shader) and past it ends them all without a word; a path
// spends at most 1 + 4 × (an environment draw's binary search over 6 × distributionSize² texels,
// the lights, the vertex) of it.
uint32_t pathsWithinLoopBudget(uint32_t distributionSize, size_t lightCount);

// RenderReferenceCS over `coverage`'s pixels (the split-sum image, whose alpha marks the spheres),
// batch after batch, each batch over the pixels still active: a pixel leaves once it has at least
// kMinSamples paths and its relative standard error is within the bound, or options.maxSamples.
// Converged when every pixel left by the bound. Stopping each pixel by its own estimate biases it
// by far less than its standard error. A batch runs as dispatches of options.pathsPerDispatch
// paths; every pixel's count of the paths that ran is checked against them, and a shortfall (a
// driver that ended the loops early) is a RenderError. `environment` is the source cube; its
// sampling distribution comes from its first mip of at most 256² texels.
ReferenceImage renderReference(const vulkan::VulkanContext& context, kernels::Kernel& kernel, const SphereGrid& grid,
                               vulkan::Image& environment, const std::vector<RenderLight>& lights, const SphereImage& coverage,
                               const ReferenceOptions& options, bake::BakeProgress& progress);

} // namespace iblkit::render
