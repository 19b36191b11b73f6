#pragma once

#include "kernels/kernel_parameters.hpp"
#include "mipped_cube.hpp"
#include "suite_environment.hpp"

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

namespace iblkit::consistency {

// The inputs the cube kernels read, made on the host so that the GPU paths and the C++
// references see the same floats.

using MippedCube = reference::MippedCube;

// The environment at `size` with `mips` mips, each made from the one above by
// DownsampleCubeCS's float arithmetic.
MippedCube environmentCube(const SuiteEnvironment& environment, uint32_t size, uint32_t mips);

// What PreviewCS reads and the size it writes.
struct PreviewInputs {
    MippedCube specular;
    MippedCube irradiance;
    uint32_t lutSize = 0;
    std::vector<float> lut; // (scale, bias) per texel
    // The recipe's lobe table and lights: G1's table and one light, a disk of 3 degrees that the
    // recipe adds from mip 2 on, with pairs of lookups about the fitted direction.
    std::vector<float> lobeTable;
    std::vector<float> lights;
    kernels::PreviewParameters parameters;
    uint32_t width = 0;
    uint32_t height = 0;
};
// A grid of columns x rows spheres of cellSize pixels over the environment at specularSize with
// all its mips, its mip 2 (its last, under 4²) as the irradiance cube and the float reference LUT.
PreviewInputs previewInputs(const SuiteEnvironment& environment, uint32_t columns, uint32_t rows, uint32_t cellSize, uint32_t specularSize, uint32_t lutSize,
                            uint32_t sampleCount);

} // namespace iblkit::consistency
