#pragma once

#include "kernels/kernel.hpp"

#include "image.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace iblkit::kernels {

// llvmpipe ends a shader loop after this many iterations, silently; a sample loop longer than
// this runs as chunks of kChunkSamples, each a dispatch that adds to an accumulator.
inline constexpr uint32_t kLoopLimit = 65535;
inline constexpr uint32_t kChunkSamples = 32768;
// The largest sample count a method takes: i and n, and so Hammersley's i / n, stay exact in
// float up to 2^24.
inline constexpr uint32_t kMaxSamples = 1u << 20;

// How a sampled method splits its loop: chunks of `chunkSamples`, or one dispatch when 0 and
// the count is within the loop limit.
uint32_t chunkSamplesFor(uint32_t samples, uint32_t requestedChunk = 0);

// A method at a sample count: its kernel of the whole-loop role, or, when the samples are
// split, its chunked kernel, dispatched chunk by chunk with the same per-sample math.
class SampledMethod {
public:
    DispatchTotals takeTotals() { return kernel_.takeTotals(); }
    uint32_t chunkSamples() const { return chunk_; } // 0: one dispatch

protected:
    SampledMethod(const vulkan::VulkanContext& context, KernelRole whole, KernelRole chunked, const std::string& method,
                  uint32_t samples, uint32_t requestedChunk, const ShaderFiles& files);
    uint32_t samples_, chunk_;
    Kernel kernel_;
};

class PrefilterMethod : public SampledMethod {
public:
    PrefilterMethod(const vulkan::VulkanContext& context, const std::string& method, uint32_t samples,
                    uint32_t requestedChunk = 0, const ShaderFiles& files = embeddedShaderFiles());
    // Writes mip `mip` of `target` (RGBA32F, storage) from `source` at `roughness`.
    void run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip, float roughness);
};

class BrdfLutMethod : public SampledMethod {
public:
    BrdfLutMethod(const vulkan::VulkanContext& context, const std::string& method, uint32_t samples,
                  uint32_t requestedChunk = 0, const ShaderFiles& files = embeddedShaderFiles());
    // Writes `lut` (R32G32_SFLOAT, storage) whole.
    void run(vulkan::Image& lut);
};

} // namespace iblkit::kernels
