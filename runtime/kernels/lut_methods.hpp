#pragma once

#include "kernels/grid_lut_method.hpp"
#include "kernels/sampled_methods.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::kernels {

// The LUT methods differ in what their count means: the document's estimator takes samples per
// texel; the polynomial (BrdfLutFitCS) its degree; the quadrature (BrdfLutQuadratureCS) takes Gauss–Legendre nodes per panel, a
// compile-time count of at most kMaxQuadratureNodes; the quadrature grid (BrdfLutGridCS, then
// BrdfLutResampleCS) takes its grid's nodes per side, each integrated at kDefaultQuadratureNodes.
inline constexpr const char* kQuadratureLutMethod = "quadrature";
inline constexpr const char* kQuadratureGridLutMethod = "quadrature-grid";
// The polynomial LUT (BrdfLutFitCS) takes its degree, 1 to 9 (reference::kMaxLutFitDegree).
inline constexpr const char* kFitLutMethod = "fit";
inline constexpr uint32_t kMaxLutFitDegree = 9;
inline constexpr uint32_t kMaxQuadratureNodes = 16;
// 7 nodes: within 6e-6 of the converged LUT at 512² on lavapipe, every texel of an RG16F LUT the
// converged value's nearest half or its neighbour (6 leaves two a step further; docs/bench.md).
inline constexpr uint32_t kDefaultQuadratureNodes = 7;
// Catmull-Rom with quadratic end neighbours needs three nodes on either side of an interval's
// ends; a grid as fine as the LUT gains nothing over the plain quadrature.
inline constexpr uint32_t kMinLutGrid = 4;
inline constexpr uint32_t kMaxLutGrid = 1024;
// The quadrature grid's nodes per side unless told otherwise. Measured on lavapipe at 512²: 192
// is 1.6e-5 from the converged LUT (RG32F's target is 1e-4) with every RG16F texel the converged
// value's nearest half or its neighbour, in 32 ms; 160 is 5.4e-5 off, 144 1.3e-4 (the grazing
// column of low roughness) and 128 leaves RG16F texels two steps off. The C++ twin measures 192
// at 6.4e-6 for a 128² LUT and 4.8e-5 for a 1024² one, both within a half step.
inline constexpr uint32_t kDefaultLutGrid = 192;

// Every method with a LUT kernel, in table order.
std::vector<std::string> lutMethods();
// The least and the largest count `method` takes. Throw std::out_of_range for a method with no
// LUT kernel.
uint32_t minLutSamplesOf(const std::string& method);
uint32_t maxLutSamplesOf(const std::string& method);
// What `method`'s count counts, for messages and the manifest.
std::string lutCountName(const std::string& method);

// A LUT method by name, whichever kernels implement it, at its count.
class LutMethod {
public:
    LutMethod(const vulkan::VulkanContext& context, const std::string& method, uint32_t count,
              const ShaderFiles& files = embeddedShaderFiles());
    // Writes `lut` (R32G32_SFLOAT, storage) whole.
    void run(vulkan::Image& lut);
    DispatchTotals takeTotals();
    uint32_t chunkSamples() const; // 0: one dispatch of the sampled estimator

private:
    std::optional<BrdfLutMethod> sampled_;
    std::optional<GridLut> grid_;
};

} // namespace iblkit::kernels
