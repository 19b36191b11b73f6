#include "kernels/specular_method.hpp"

#include <stdexcept>

namespace iblkit::kernels {

bool isConvolutionMethod(const std::string& method) {
    for (const auto& kernel : kernelTable())
        if (kernel.method == method && kernel.role == KernelRole::PrefilterConvolution) return true;
    kernelFor(KernelRole::Prefilter, method); // throws for a method with neither
    return false;
}

std::vector<std::string> specularMethods() {
    auto methods = methodsOf(KernelRole::Prefilter);
    for (const auto& method : methodsOf(KernelRole::PrefilterConvolution)) methods.push_back(method);
    return methods;
}

uint32_t maxSamplesOf(const std::string& method) {
    return isConvolutionMethod(method) ? kMaxConvolutionBudget : kMaxSamples;
}

SpecularMethod::SpecularMethod(const vulkan::VulkanContext& context, const std::string& method, uint32_t samples,
                               const ShaderFiles& files) {
    if (isConvolutionMethod(method))
        convolution_.emplace(context, method, samples, files);
    else
        sampled_.emplace(context, method, samples, 0, files);
}

void SpecularMethod::run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip,
                         float roughness) {
    if (convolution_) return convolution_->run(source, target, mip, roughness);
    sampled_->run(source, sampler, target, mip, roughness);
}

DispatchTotals SpecularMethod::takeTotals() {
    return convolution_ ? convolution_->takeTotals() : sampled_->takeTotals();
}

uint32_t SpecularMethod::chunkSamples() const { return sampled_ ? sampled_->chunkSamples() : 0; }

} // namespace iblkit::kernels
