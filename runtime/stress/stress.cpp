#include "stress.hpp"

#include "egl_context.hpp"

namespace iblkit::stress {

bool StressReport::passed() const {
    for (const auto& row : probes.rows)
        if (!row.passed) return false;
    for (const auto& point : probes.singular)
        if (point.calledByBake) return false;
    for (const auto& row : environments)
        if (!row.passed) return false;
    for (const auto& row : sampleCounts)
        if (!row.passed) return false;
    for (const auto& row : inputs)
        if (!row.passed()) return false;
    return true;
}

StressReport runStress(const vulkan::VulkanContext& context, const StressOptions& options) {
    const opengl::EglContext gl;
    auto suiteOptions = consistency::defaultSuiteOptions(options.manifest);
    consistency::SuiteRun run(context, gl, suiteOptions);
    StressReport report;
    report.openGlRenderer = gl.renderer();
    report.probes = sweepProbes(run);
    report.environments = sweepEnvironments(run, suiteOptions, environmentCases(options.reduced, options.blenderWorlds));
    report.sampleCounts = sweepSampleCounts(run, options.reduced);
    report.inputs = checkInputPolicies();
    return report;
}

} // namespace iblkit::stress
