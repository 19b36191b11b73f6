#pragma once

#include "compile_options.hpp"
#include "error_stats.hpp"
#include "vulkan_context.hpp"

#include <string>
#include <vector>

namespace iblkit::consistency {

struct SuiteOptions {
    std::vector<uint32_t> lutSizes{512, 32};
    uint32_t prefilterSize = 32;
    uint32_t environmentSize = 64;
    std::vector<float> roughnesses{0.0f, 0.25f, 0.5f, 1.0f};
    uint32_t sampleCount = 1024;
    // The shaders under test; from hlsl/shaders.json unless a test substitutes others.
    compiler::CompileOptions lutShader;
    compiler::CompileOptions prefilterShader;
};

// The options the suite runs the seed shaders with: the manifest's, with SAMPLE_COUNT set and
// the LUT written as R32G32_SFLOAT (so that the comparison measures arithmetic, not storage).
SuiteOptions defaultSuiteOptions(const std::string& manifest = "hlsl/shaders.json", uint32_t sampleCount = 1024);

// Bounds on the largest absolute error and the RMS error of a path, against each reference.
struct Bounds {
    double maxVsFloat, rmsVsFloat, maxVsDouble, rmsVsDouble;
};

struct ConsistencyRow {
    std::string path;
    std::string output;
    ErrorStats vsFloat;
    ErrorStats vsDouble;
    Bounds bounds;
    bool isReference; // the float reference against the double one: shown, not judged
    bool passed;
};

// Every path of every output — the four Vulkan paths and d, the GLSL form on OpenGL 4.5 through
// EGL — against the C++ reference in float and in double; the first row of each output is the
// float reference itself against the double one.
struct ConsistencyResult {
    std::vector<ConsistencyRow> rows;
    std::string openGlRenderer;
};
ConsistencyResult runConsistency(const vulkan::VulkanContext& context, const SuiteOptions& options);

// The bounds, and why each is those numbers (boundsRationale).
Bounds lutBounds(uint32_t size);
Bounds prefilterBounds();
std::string boundsRationale();

std::string renderMarkdown(const std::vector<ConsistencyRow>& rows, const vulkan::VulkanContext& context,
                           const std::string& openGlRenderer, const SuiteOptions& options, const std::string& command);

// The name of path d in the rows.
std::string_view openGlPathName();

} // namespace iblkit::consistency
