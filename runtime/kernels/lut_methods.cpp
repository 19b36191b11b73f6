#include "kernels/lut_methods.hpp"

namespace iblkit::kernels {

std::vector<std::string> lutMethods() { return methodsOf(KernelRole::BrdfLut); }

uint32_t maxLutSamplesOf(const std::string& method) {
    kernelFor(KernelRole::BrdfLut, method); // throws for a method with no LUT kernel
    return method == kQuadratureLutMethod ? kMaxQuadratureNodes : kMaxSamples;
}

std::string lutCountName(const std::string& method) {
    return method == kQuadratureLutMethod ? "nodes per panel" : "samples";
}

} // namespace iblkit::kernels
