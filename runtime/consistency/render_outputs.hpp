#pragma once

#include "suite_inputs.hpp"
#include "suite_run.hpp"

#include "kernels/kernel_parameters.hpp"

namespace iblkit::consistency {

// RenderReferenceCS (both materials) and SplitSumSpheresCS over a small sphere grid lit by the
// suite's environment (and, for the reference, a directional, a point and an area light). No C++
// reference: the paths are compared with path a.
void addRenderOutputs(SuiteRun& run);

// What SplitSumSpheresCS (and ForwardSpheres) read over the suite's grid of spheres, of 8-pixel
// cells: the spheres' materials, the maps and the parameters; and its image on one path.
const std::vector<float>& sphereMaterials();
PreviewInputs splitSumMaps(const SuiteOptions& options);
kernels::RenderSplitSumParameters splitSumParameters(const PreviewInputs& maps);
std::vector<float> gpuSplitSum(const vulkan::VulkanContext& context, const PathProgram& program, const PreviewInputs& inputs);

} // namespace iblkit::consistency
