#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace iblkit::consistency {

// An RGBA panorama, row 0 at the zenith.
struct Panorama {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> texels;
};

// The environment the suite's cube kernels read, at whatever size each output needs: mip 0 of
// a cube (RGBA floats, face +X..-Z, row, column) and a width x width/2 panorama. The suite runs
// on the test environment; iblkit stress swaps in its extremes.
struct SuiteEnvironment {
    std::string name;
    std::function<std::vector<float>(uint32_t size)> cube;
    std::function<Panorama(uint32_t width)> panorama;
};

// reference::CubeEnvironment::testRadiance at each texel's centre.
SuiteEnvironment testSuiteEnvironment();

} // namespace iblkit::consistency
