#pragma once

#include "suite_run.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::stress {

// The documents' estimators at one sample count, each against the same samples summed in double.
struct GrowthRow {
    std::string output;
    uint32_t samples = 0;
    // Largest absolute errors: the C++ float twin, one accumulator over every sample (the
    // documents' loop as written); the documents' kernel on Vulkan (none past llvmpipe's loop
    // limit); the kit's chunked kernel on Vulkan and on OpenGL.
    double singleLoopFloat = 0;
    std::optional<double> documentKernel;
    double chunkedVulkan = 0, chunkedOpenGl = 0;
    size_t nonFinite = 0; // over all four
    double bound = 0;     // on both chunked errors
    bool passed = false;
};

// The LUT (8², IntegrateBRDF) and the prefilter (the test environment at 16² onto 2² faces,
// roughness 0.5) at 1, 2^4, 2^8, ... 2^20 samples (reduced: 1, 2^8, 2^16).
std::vector<GrowthRow> sweepSampleCounts(const consistency::SuiteRun& run, bool reduced);

} // namespace iblkit::stress
