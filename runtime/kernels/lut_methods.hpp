#pragma once

#include "kernels/sampled_methods.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::kernels {

// The LUT methods differ in what their count means: the document's estimator takes samples per
// texel; the quadrature (BrdfLutQuadratureCS) takes Gauss–Legendre nodes per panel, a
// compile-time count of at most kMaxQuadratureNodes.
inline constexpr const char* kQuadratureLutMethod = "quadrature";
inline constexpr uint32_t kMaxQuadratureNodes = 16;
// 7 nodes: within 6e-6 of the converged LUT at 512² on lavapipe, every texel of an RG16F LUT the
// converged value's nearest half or its neighbour (6 leaves two a step further; docs/bench.md).
inline constexpr uint32_t kDefaultQuadratureNodes = 7;

// Every method with a LUT kernel, in table order.
std::vector<std::string> lutMethods();
// The largest count `method` takes. Throws std::out_of_range for a method with no LUT kernel.
uint32_t maxLutSamplesOf(const std::string& method);
// What `method`'s count counts, for messages and the manifest.
std::string lutCountName(const std::string& method);

} // namespace iblkit::kernels
