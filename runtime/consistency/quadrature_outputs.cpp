// The quadrature LUT (BrdfLutQuadratureCS), the quadrature grid's two kernels (BrdfLutGridCS,
// BrdfLutResampleCS) and the polynomial LUT (BrdfLutFitCS) against their C++ twins, in float
// and in double.
#include "gpu_bake.hpp"
#include "grid_lut_bake.hpp"
#include "lut_fit.hpp"
#include "lut_grid.hpp"
#include "kernels/lut_methods.hpp"
#include "lut_quadrature.hpp"
#include "suite_run.hpp"

#include <fmt/core.h>

namespace iblkit::consistency {

void addQuadratureLutOutput(SuiteRun& run) {
    const uint32_t size = run.options.quadratureLutSize, nodes = kernels::kDefaultQuadratureNodes;
    addOutput(run, {"BrdfLutQuadratureCS", fmt::format("LUT {}², {} nodes per panel", size, nodes), quadratureLutBounds()},
              [&] { return References{reference::brdfLutQuadrature<float>(size, nodes), reference::brdfLutQuadrature<double>(size, nodes)}; },
              [&](const PathProgram& program) { return gpuBrdfLut(run.vulkan, program, size); },
              [&](const OpenGlForm& form) { return glBrdfLut(run.gl, form, size); });
}

void addFitLutOutput(SuiteRun& run) {
    if (!run.runs("BrdfLutFitCS")) return; // the fit alone is 3 s of converged quadrature
    const uint32_t size = run.options.quadratureLutSize, degree = kSuiteLutFitDegree;
    // Both references evaluate the coefficients the shader holds, the fit's rounded to float.
    std::vector<glm::vec2> coefficients;
    std::vector<glm::dvec2> coefficientsInDouble;
    for (const auto& c : reference::fitBrdfLut(degree)) {
        coefficients.emplace_back(c);
        coefficientsInDouble.emplace_back(coefficients.back());
    }
    addOutput(run, {"BrdfLutFitCS", fmt::format("LUT {}², a polynomial of degree {}", size, degree), lutFitBounds()},
              [&] { return References{reference::brdfLutFromFit<float>(size, coefficients),
               reference::brdfLutFromFit<double>(size, coefficientsInDouble)}; },
              [&](const PathProgram& program) { return gpuBrdfLut(run.vulkan, program, size); },
              [&](const OpenGlForm& form) { return glBrdfLut(run.gl, form, size); });
}

void addGridLutOutputs(SuiteRun& run) {
    const uint32_t gridSize = run.options.lutGridSize, size = run.options.quadratureLutSize;
    const uint32_t nodes = kernels::kDefaultQuadratureNodes;
    addOutput(run, {"BrdfLutGridCS", fmt::format("LUT grid {}², {} nodes per panel", gridSize, nodes), lutGridBounds()},
              [&] { return References{reference::brdfLutGridNodes<float>(gridSize, nodes), reference::brdfLutGridNodes<double>(gridSize, nodes)}; },
              [&](const PathProgram& program) { return gpuBrdfLutGrid(run.vulkan, program, gridSize); },
              [&](const OpenGlForm& form) { return glBrdfLutGrid(run.gl, form, gridSize); });
    if (!run.runs("BrdfLutResampleCS")) return;
    // Every path resamples the same grid (the double nodes, rounded to float), so that the row
    // measures the interpolation alone.
    const auto nodesInDouble = reference::brdfLutGridNodes<double>(gridSize, nodes);
    const std::vector<float> grid(nodesInDouble.begin(), nodesInDouble.end());
    const std::vector<double> gridInDouble(grid.begin(), grid.end());
    addOutput(run, {"BrdfLutResampleCS", fmt::format("LUT {}² from a {}² grid", size, gridSize), lutResampleBounds()},
              [&] { return References{reference::resampleBrdfLutGrid<float>(grid, gridSize, size),
               reference::resampleBrdfLutGrid<double>(gridInDouble, gridSize, size)}; },
              [&](const PathProgram& program) { return gpuBrdfLutResample(run.vulkan, program, grid, gridSize, size); },
              [&](const OpenGlForm& form) { return glBrdfLutResample(run.gl, form, grid, gridSize, size); });
}

} // namespace iblkit::consistency
