#pragma once

#include "kernels/convolution_method.hpp"
#include "kernels/sampled_methods.hpp"

#include <optional>
#include <string>
#include <vector>

namespace iblkit::kernels {

// Every method with a prefilter kernel (sampled or convolution), in hlsl/shaders.json's order.
std::vector<std::string> specularMethods();
// Whether `method`'s prefilter is the convolution (ClusterCube + PrefilterConvolution) rather
// than a sampled estimator (Prefilter, PrefilterChunk). Throws std::out_of_range for an unknown method.
bool isConvolutionMethod(const std::string& method);

// A prefilter method by name, whichever kernels implement it. `samples` is the sample count of
// a sampled method, and the budget of terms per output texel of the convolution.
class SpecularMethod {
public:
    SpecularMethod(const vulkan::VulkanContext& context, const std::string& method, uint32_t samples,
                   const ShaderFiles& files = embeddedShaderFiles());
    // Writes mip `mip` of `target` (RGBA32F, storage) from `source` at `roughness`; a sampled
    // method reads `source` through `sampler`.
    void run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip, float roughness);
    DispatchTotals takeTotals();
    uint32_t chunkSamples() const; // 0 for one dispatch per mip
    // The HLSL files it runs, as hlsl/shaders.json names them.
    std::vector<std::string> shaderSources() const;

private:
    std::string method_;
    std::optional<PrefilterMethod> sampled_;
    std::optional<ConvolutionPrefilter> convolution_;
};

} // namespace iblkit::kernels
