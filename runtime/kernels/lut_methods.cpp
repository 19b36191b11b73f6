#include "kernels/lut_methods.hpp"

namespace iblkit::kernels {

std::vector<std::string> lutMethods() {
    auto methods = methodsOf(KernelRole::BrdfLut);
    for (const auto& method : methodsOf(KernelRole::BrdfLutGrid)) methods.push_back(method);
    return methods;
}

uint32_t minLutSamplesOf(const std::string& method) {
    maxLutSamplesOf(method); // throws for a method with no LUT kernel
    return method == kQuadratureGridLutMethod ? kMinLutGrid : 1;
}

uint32_t maxLutSamplesOf(const std::string& method) {
    if (method == kQuadratureGridLutMethod) {
        kernelFor(KernelRole::BrdfLutGrid, method);
        return kMaxLutGrid;
    }
    kernelFor(KernelRole::BrdfLut, method); // throws for a method with no LUT kernel
    if (method == kFitLutMethod) return kMaxLutFitDegree;
    return method == kQuadratureLutMethod ? kMaxQuadratureNodes : kMaxSamples;
}

std::string lutCountName(const std::string& method) {
    if (method == kQuadratureGridLutMethod) return "grid nodes per side";
    if (method == kFitLutMethod) return "polynomial degree";
    return method == kQuadratureLutMethod ? "nodes per panel" : "samples";
}

LutMethod::LutMethod(const vulkan::VulkanContext& context, const std::string& method, uint32_t count,
                     const ShaderFiles& files) {
    if (method == kQuadratureGridLutMethod)
        grid_.emplace(context, count, kDefaultQuadratureNodes, files);
    else
        sampled_.emplace(context, method, count, 0, files);
}

void LutMethod::run(vulkan::Image& lut) { grid_ ? grid_->run(lut) : sampled_->run(lut); }

DispatchTotals LutMethod::takeTotals() { return grid_ ? grid_->takeTotals() : sampled_->takeTotals(); }

uint32_t LutMethod::chunkSamples() const { return sampled_ ? sampled_->chunkSamples() : 0; }

} // namespace iblkit::kernels
