#include "measurements.hpp"

#include "bake_settings.hpp"
#include "converged_prefilter.hpp"
#include "face_seams.hpp"
#include "kernels/specular_method.hpp"

#include <fmt/core.h>

#include <cmath>

namespace iblkit::bench {

struct SpecularBench::MipReference {
    uint32_t mip;
    float roughness;
    std::vector<reference::PrefilterTexel> texels;
    std::vector<glm::dvec3> radiance;
    std::vector<reference::PrefilterTexel> seamTexels; // pairs across face edges, flattened
    double seamJump;                                   // the converged values' own
};

namespace {

// The key names everything the converged values depend on; "v1" changes with their math.
std::string prefilterKey(const reference::MippedCube& cube, uint32_t mipSize, float roughness, const BenchOptions& options) {
    const auto source = cube.mip(0);
    return ReferenceCache::key(fmt::format("converged prefilter v1 size {} roughness {:a} output {} texels {} seed {}",
                                           cube.size, roughness, mipSize, options.texelsPerMip, options.seed),
                               std::as_bytes(source));
}

// The texels of the pairs across the face edges, pair after pair.
std::vector<reference::PrefilterTexel> seamTexels(uint32_t mipSize, uint32_t perEdge) {
    std::vector<reference::PrefilterTexel> texels;
    for (const auto& pair : reference::faceEdgePairs(mipSize, perEdge)) texels.insert(texels.end(), pair.begin(), pair.end());
    return texels;
}

std::string seamKey(const reference::MippedCube& cube, uint32_t mipSize, float roughness, uint32_t perEdge) {
    return ReferenceCache::key(fmt::format("converged prefilter seams v1 size {} roughness {:a} output {} per edge {}",
                                           cube.size, roughness, mipSize, perEdge),
                               std::as_bytes(cube.mip(0)));
}

std::vector<glm::dvec3> texelRadiance(const std::vector<float>& specular, const vulkan::Image& image, uint32_t mip,
                                      const std::vector<reference::PrefilterTexel>& texels) {
    const uint32_t width = image.mipWidth(mip);
    std::vector<glm::dvec3> radiance;
    for (const auto& texel : texels) {
        const float* at = &specular[image.valueOffset(mip, texel.face) + (size_t(texel.y) * width + texel.x) * 4];
        radiance.emplace_back(at[0], at[1], at[2]);
    }
    return radiance;
}

MipError mipError(const std::vector<float>& specular, const vulkan::Image& image, uint32_t mip, float roughness,
                  const std::vector<reference::PrefilterTexel>& texels, const std::vector<glm::dvec3>& reference) {
    const auto radiance = texelRadiance(specular, image, mip, texels);
    ErrorSummary errors;
    for (size_t i = 0; i < texels.size(); ++i) errors.add(relativeLuminanceError(radiance[i], reference[i]));
    return {mip, roughness, uint32_t(texels.size()), errors.rms(), errors.max()};
}

} // namespace

SpecularBench::SpecularBench(const vulkan::VulkanContext& context, vulkan::Image& source, const reference::MippedCube& cube,
                             const BenchOptions& options, const ReferenceCache& cache)
    : context_(context), source_(source), options_(options) {
    mips_ = bake::chainDownTo(cube.size, profiles::defaultProfile().lastMipSize); // the bake's default chain
    for (uint32_t mip = 1; mip < mips_; ++mip) {
        const uint32_t mipSize = cube.size >> mip;
        const float roughness = bake::roughnessOfMip(mip, mips_);
        auto texels = reference::seededPrefilterTexels(mipSize, options.texelsPerMip, options.seed + mip);
        const auto values = cache.getOrCompute(prefilterKey(cube, mipSize, roughness, options), texels.size() * 3, [&] {
            return flatten(reference::convergedPrefilter(cube.mip(0), cube.size, double(roughness), mipSize, texels));
        });
        auto seams = seamTexels(mipSize, options.seamPairsPerEdge);
        const auto seamValues = cache.getOrCompute(seamKey(cube, mipSize, roughness, options.seamPairsPerEdge), seams.size() * 3, [&] {
            return flatten(reference::convergedPrefilter(cube.mip(0), cube.size, double(roughness), mipSize, seams));
        });
        const double seamJump = reference::largestSeamJump(unflatten(seamValues));
        references_.push_back({mip, roughness, std::move(texels), unflatten(values), std::move(seams), seamJump});
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
        result.seamJump = std::max(result.seamJump, reference::largestSeamJump(texelRadiance(values, specular, reference.mip, reference.seamTexels)));
        result.referenceSeamJump = std::max(result.referenceSeamJump, reference.seamJump);
    }
    return result;
}

} // namespace iblkit::bench
