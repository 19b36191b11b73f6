#include "kernels/sampled_methods.hpp"

#include "kernels/kernel_steps.hpp"
#include "kernels/lut_methods.hpp"

#include <algorithm>
#include <stdexcept>

namespace iblkit::kernels {
namespace {

std::map<std::string, std::string> sampleCountDefine(uint32_t samples) {
    if (samples == 0 || samples > kMaxSamples)
        throw std::invalid_argument("a sample count must be between 1 and " + std::to_string(kMaxSamples) + ", not " +
                                    std::to_string(samples));
    return {{"SAMPLE_COUNT", std::to_string(samples)}};
}

// The LUT is written as 32-bit floats; the bake rounds it to its file's format on the host.
std::map<std::string, std::string> imageFormats(KernelRole role) {
    if (role == KernelRole::BrdfLut) return {{"Precomputed", "rg32f"}};
    if (role == KernelRole::BrdfLutChunk) return {{"Precomputed", "rg32f"}, {"Accumulated", "rg32f"}};
    return {};
}

KernelProgram compileSampled(KernelRole role, const std::string& method, uint32_t samples, const ShaderFiles& files) {
    const auto methods = methodsOf(role);
    const bool chunked = role == KernelRole::PrefilterChunk || role == KernelRole::BrdfLutChunk;
    if (chunked && std::find(methods.begin(), methods.end(), method) == methods.end())
        throw std::invalid_argument("the method '" + method + "' has no chunked kernel, so it takes at most " +
                                    std::to_string(kLoopLimit) + " samples, not " + std::to_string(samples));
    return compileKernel(kernelFor(role, method), sampleCountDefine(samples), imageFormats(role), files);
}

uint32_t checkedLutCount(const std::string& method, uint32_t samples) {
    const uint32_t most = maxLutSamplesOf(method);
    if (samples == 0 || samples > most)
        throw std::invalid_argument("the LUT method '" + method + "' takes 1 to " + std::to_string(most) + " " +
                                    lutCountName(method) + ", not " + std::to_string(samples));
    return samples;
}

} // namespace

uint32_t chunkSamplesFor(uint32_t samples, uint32_t requestedChunk) {
    if (requestedChunk > kLoopLimit)
        throw std::invalid_argument("a chunk of " + std::to_string(requestedChunk) + " samples passes the loop limit of " +
                                    std::to_string(kLoopLimit));
    if (requestedChunk) return requestedChunk;
    return samples > kLoopLimit ? kChunkSamples : 0;
}

SampledMethod::SampledMethod(const vulkan::VulkanContext& context, KernelRole whole, KernelRole chunked,
                             const std::string& method, uint32_t samples, uint32_t requestedChunk, const ShaderFiles& files)
    : samples_(samples), chunk_(chunkSamplesFor(samples, requestedChunk)),
      kernel_(context, compileSampled(chunk_ ? chunked : whole, method, samples, files)) {}

PrefilterMethod::PrefilterMethod(const vulkan::VulkanContext& context, const std::string& method, uint32_t samples,
                                 uint32_t requestedChunk, const ShaderFiles& files)
    : SampledMethod(context, KernelRole::Prefilter, KernelRole::PrefilterChunk, method, samples, requestedChunk, files) {}

void PrefilterMethod::run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip,
                          float roughness) {
    if (chunk_) return runPrefilterChunked(kernel_, source, sampler, target, mip, roughness, samples_, chunk_);
    runPrefilter(kernel_, source, sampler, target, mip, {roughness});
}

BrdfLutMethod::BrdfLutMethod(const vulkan::VulkanContext& context, const std::string& method, uint32_t samples,
                             uint32_t requestedChunk, const ShaderFiles& files)
    : SampledMethod(context, KernelRole::BrdfLut, KernelRole::BrdfLutChunk, method, checkedLutCount(method, samples),
                    requestedChunk, files) {}

void BrdfLutMethod::run(vulkan::Image& lut) {
    if (chunk_) return runBrdfLutChunked(kernel_, lut, samples_, chunk_);
    runBrdfLut(kernel_, lut);
}

} // namespace iblkit::kernels
