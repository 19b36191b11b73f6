#pragma once

#include "environment_sweep.hpp"
#include "input_cases.hpp"
#include "probe_sweep.hpp"
#include "sample_growth.hpp"
#include "context_options.hpp"

#include <filesystem>
#include <string>

namespace iblkit::bake {
class BakeProgress;
}

namespace iblkit::stress {

struct StressOptions {
    bool reduced = false; // the test suite's set: fewer environments and sample counts
    // Where Blender's world HDRIs are (bench::blenderWorlds); empty: without them.
    std::filesystem::path blenderWorlds;
    std::string manifest = "hlsl/shaders.json"; // the kernels' sources (a test may break a copy)
};

struct StressReport {
    ProbeSweep probes;
    std::vector<EnvironmentRow> environments;
    std::vector<GrowthRow> sampleCounts;
    std::vector<InputRow> inputs;
    std::string openGlRenderer;
    bool passed() const;
};

// `progress`, when given, gets a step per sweep.
StressReport runStress(const vulkan::VulkanContext& context, const StressOptions& options,
                       bake::BakeProgress* progress = nullptr);

std::string renderStabilityMarkdown(const StressReport& report, const vulkan::VulkanContext& context,
                                    const std::string& command);

} // namespace iblkit::stress
