#include "measurements.hpp"

#include "bake_settings.hpp"
#include "converged_prefilter.hpp"
#include "kernels/specular_method.hpp"

#include <fmt/core.h>

#include <cmath>

namespace iblkit::bench {

struct SpecularBench::MipReference {
    uint32_t mip;
    float roughness;
    std::vector<reference::PrefilterTexel> texels;
    std::vector<glm::dvec3> radiance;
};

namespace {

// The key names everything the converged values depend on; "v1" changes with their math.
std::string prefilterKey(const reference::MippedCube& cube, uint32_t mipSize, float roughness, const BenchOptions& options) {
    const auto source = cube.mip(0);
    return ReferenceCache::key(fmt::format("converged prefilter v1 size {} roughness {:a} output {} texels {} seed {}",
                                           cube.size, roughness, mipSize, options.texelsPerMip, options.seed),
                               std::as_bytes(source));
}

MipError mipError(const std::vector<float>& specular, const vulkan::Image& image, uint32_t mip, float roughness,
                  const std::vector<reference::PrefilterTexel>& texels, const std::vector<glm::dvec3>& reference) {
    const uint32_t width = image.mipWidth(mip);
    ErrorSummary errors;
    for (size_t i = 0; i < texels.size(); ++i) {
        const auto& texel = texels[i];
        const float* at = &specular[image.valueOffset(mip, texel.face) + (size_t(texel.y) * width + texel.x) * 4];
        errors.add(relativeLuminanceError({at[0], at[1], at[2]}, reference[i]));
    }
    return {mip, roughness, uint32_t(texels.size()), errors.rms(), errors.max()};
}

} // namespace

SpecularBench::SpecularBench(const vulkan::VulkanContext& context, vulkan::Image& source, const reference::MippedCube& cube,
                             const BenchOptions& options, const ReferenceCache& cache)
    : context_(context), source_(source), options_(options) {
    bake::BakeSettings defaults;
    mips_ = bake::resolvedMips(defaults, cube.size);
    for (uint32_t mip = 1; mip < mips_; ++mip) {
        const uint32_t mipSize = cube.size >> mip;
        const float roughness = bake::roughnessOfMip(mip, mips_);
        auto texels = reference::seededPrefilterTexels(mipSize, options.texelsPerMip, options.seed + mip);
        const auto values = cache.getOrCompute(prefilterKey(cube, mipSize, roughness, options), texels.size() * 3, [&] {
            return flatten(reference::convergedPrefilter(cube.mip(0), cube.size, double(roughness), mipSize, texels));
        });
        references_.push_back({mip, roughness, std::move(texels), unflatten(values)});
    }
}

SpecularBench::~SpecularBench() = default;

BenchResult SpecularBench::measure(const std::string& method, uint32_t samples) {
    kernels::SpecularMethod prefilter(context_, method, samples, options_.shaderFiles);
    const uint32_t size = source_.desc().width;
    const auto& rgba32 = vulkan::texelFormatNamed("R32G32B32A32_SFLOAT");
    vulkan::Image specular(context_, {"Specular", &rgba32, size, size, 6, mips_, true, true});
    const vulkan::Sampler linear(context_, {});
    const auto timing = timeRepeated(options_.repeat, [&] {
        for (uint32_t mip = 1; mip < mips_; ++mip)
            prefilter.run(source_, linear, specular, mip, bake::roughnessOfMip(mip, mips_));
        return prefilter.takeTotals().deviceMilliseconds;
    });
    const auto values = specular.download(context_);
    BenchResult result{BenchOutput::Specular, {}, method, samples, prefilter.chunkSamples(),
                       timing.deviceMilliseconds, timing.wallMilliseconds, options_.repeat, 0, 0, {}};
    for (const auto& reference : references_) {
        result.mips.push_back(mipError(values, specular, reference.mip, reference.roughness, reference.texels,
                                       reference.radiance));
        result.errorRms = std::max(result.errorRms, result.mips.back().rms);
        result.errorMax = std::max(result.errorMax, result.mips.back().max);
    }
    return result;
}

} // namespace iblkit::bench
