#include "kernels/specular_method.hpp"

#include "pyramid_fit.hpp"

#include <algorithm>
#include <stdexcept>

namespace iblkit::kernels {
namespace {

bool hasKernel(KernelRole role, const std::string& method) {
    const auto methods = methodsOf(role);
    return std::find(methods.begin(), methods.end(), method) != methods.end();
}

} // namespace

SpecularKind specularKindOf(const std::string& method) {
    if (hasKernel(KernelRole::PrefilterConvolution, method)) return SpecularKind::Convolution;
    if (hasKernel(KernelRole::PrefilterTable, method)) return SpecularKind::Table;
    if (hasKernel(KernelRole::PrefilterPyramid, method)) return SpecularKind::Pyramid;
    if (hasKernel(KernelRole::PrefilterRing, method)) return SpecularKind::MipChain;
    kernelFor(KernelRole::Prefilter, method); // throws for a method with none
    return SpecularKind::Sampled;
}

bool isConvolutionMethod(const std::string& method) { return specularKindOf(method) == SpecularKind::Convolution; }

std::vector<std::string> specularMethods() {
    auto methods = methodsOf(KernelRole::Prefilter);
    for (const auto role : {KernelRole::PrefilterTable, KernelRole::PrefilterPyramid, KernelRole::PrefilterRing,
                            KernelRole::PrefilterConvolution})
        for (const auto& method : methodsOf(role))
            if (std::find(methods.begin(), methods.end(), method) == methods.end()) methods.push_back(method);
    return methods;
}

uint32_t maxSamplesOf(const std::string& method) {
    switch (specularKindOf(method)) {
    case SpecularKind::Convolution: return kMaxConvolutionBudget;
    case SpecularKind::Table: return kLoopLimit;
    case SpecularKind::Pyramid: return reference::kMaxPyramidReads;
    case SpecularKind::MipChain: return 1;
    case SpecularKind::Sampled: break;
    }
    return hasKernel(KernelRole::PrefilterChunk, method) ? kMaxSamples : kLoopLimit;
}

SpecularMethod::SpecularMethod(const vulkan::VulkanContext& context, const std::string& method, uint32_t samples,
                               const ShaderFiles& files, uint32_t expectedSourceSize) {
    switch (specularKindOf(method)) {
    case SpecularKind::Convolution: convolution_.emplace(context, method, samples, files, expectedSourceSize); break;
    case SpecularKind::Table: table_.emplace(context, method, samples, files); break;
    case SpecularKind::Pyramid: pyramid_.emplace(context, method, samples, files); break;
    case SpecularKind::MipChain:
        if (samples != 1)
            throw std::invalid_argument("the " + method + " method takes no sample count (1), not " +
                                        std::to_string(samples));
        mipChain_.emplace(context, method, files);
        break;
    case SpecularKind::Sampled: sampled_.emplace(context, method, samples, 0, files); break;
    }
}

void SpecularMethod::run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip,
                         float roughness) {
    if (convolution_) return convolution_->run(source, target, mip, roughness);
    if (table_) return table_->run(source, sampler, target, mip, roughness);
    if (pyramid_) return pyramid_->run(source, sampler, target, mip, roughness);
    if (mipChain_) return mipChain_->run(source, sampler, target, mip, roughness);
    sampled_->run(source, sampler, target, mip, roughness);
}

void SpecularMethod::setWeighting(shading::LobeWeighting weighting) {
    if (convolution_) return convolution_->setWeighting(weighting);
    if (weighting != shading::LobeWeighting::NdotL)
        throw std::invalid_argument("only the convolution prefilters a lobe weighted by G1");
}

DispatchTotals SpecularMethod::takeTotals() {
    if (convolution_) return convolution_->takeTotals();
    if (pyramid_) return pyramid_->takeTotals();
    if (mipChain_) return mipChain_->takeTotals();
    return table_ ? table_->takeTotals() : sampled_->takeTotals();
}

uint32_t SpecularMethod::chunkSamples() const { return sampled_ ? sampled_->chunkSamples() : 0; }

void SpecularMethod::releaseSourceData() {
    if (convolution_) convolution_->releasePyramids();
}

} // namespace iblkit::kernels
