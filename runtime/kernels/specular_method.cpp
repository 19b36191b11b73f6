#include "kernels/specular_method.hpp"

#include <algorithm>
#include <stdexcept>

namespace iblkit::kernels {

std::vector<std::string> specularMethods() {
    std::vector<std::string> methods;
    for (const auto& kernel : kernelTable())
        if ((kernel.role == KernelRole::Prefilter || kernel.role == KernelRole::PrefilterConvolution) &&
            std::find(methods.begin(), methods.end(), kernel.method) == methods.end())
            methods.push_back(kernel.method);
    return methods;
}

bool isConvolutionMethod(const std::string& method) {
    for (const auto& kernel : kernelTable())
        if (kernel.method == method && kernel.role == KernelRole::PrefilterConvolution) return true;
    kernelFor(KernelRole::Prefilter, method); // throws for a method with neither
    return false;
}

SpecularMethod::SpecularMethod(const vulkan::VulkanContext& context, const std::string& method, uint32_t samples,
                               const ShaderFiles& files)
    : method_(method) {
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

std::vector<std::string> SpecularMethod::shaderSources() const {
    const auto source = [](const KernelEntry& kernel) { return kernel.options.source.generic_string(); };
    if (convolution_)
        return {source(kernelFor(KernelRole::ClusterCube)), source(kernelFor(KernelRole::PrefilterConvolution, method_))};
    const auto role = sampled_->chunkSamples() ? KernelRole::PrefilterChunk : KernelRole::Prefilter;
    return {source(kernelFor(role, method_))};
}

} // namespace iblkit::kernels
