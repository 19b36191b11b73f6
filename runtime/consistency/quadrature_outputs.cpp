// The quadrature LUT (BrdfLutQuadratureCS) against its C++ twin, in float and in double.
#include "gpu_bake.hpp"
#include "kernels/lut_methods.hpp"
#include "lut_quadrature.hpp"
#include "suite_run.hpp"

#include <fmt/core.h>

namespace iblkit::consistency {

void addQuadratureLutOutput(SuiteRun& run) {
    const uint32_t size = run.options.quadratureLutSize, nodes = kernels::kDefaultQuadratureNodes;
    addOutput(run, {"BrdfLutQuadratureCS", fmt::format("LUT {}², {} nodes per panel", size, nodes), quadratureLutBounds()},
              {reference::brdfLutQuadrature<float>(size, nodes), reference::brdfLutQuadrature<double>(size, nodes)},
              [&](const PathProgram& program) { return gpuBrdfLut(run.vulkan, program, size); },
              [&](const OpenGlForm& form) { return glBrdfLut(run.gl, form, size); });
}

} // namespace iblkit::consistency
