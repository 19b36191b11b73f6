#include "stress.hpp"

#include "bake_progress.hpp"
#include "egl_context.hpp"

namespace iblkit::stress {

bool StressReport::passed() const {
    for (const auto& row : probes.rows)
        if (!row.passed) return false;
    for (const auto& point : probes.singular)
        if (point.calledByBake) return false;
    for (const auto& row : environments)
        if (!row.passed) return false;
    if (!knownDivergencesShow(environments)) return false;
    for (const auto& row : sampleCounts)
        if (!row.passed) return false;
    for (const auto& row : inputs)
        if (!row.passed()) return false;
    return true;
}

StressReport runStress(const vulkan::VulkanContext& context, const StressOptions& options, bake::BakeProgress* progress) {
    const opengl::EglContext gl;
    auto suiteOptions = consistency::defaultSuiteOptions(options.manifest);
    consistency::SuiteRun run(context, gl, suiteOptions);
    StressReport report;
    report.openGlRenderer = gl.renderer();
    const auto step = [&](const char* name, const auto& sweep) {
        if (progress) progress->begin(name);
        sweep();
        if (progress) progress->end();
    };
    step("probes", [&] { report.probes = sweepProbes(run); });
    step("environments", [&] {
        report.environments = sweepEnvironments(run, suiteOptions, environmentCases(options.reduced, options.blenderWorlds));
    });
    step("sample counts", [&] { report.sampleCounts = sweepSampleCounts(run, options.reduced); });
    step("input policies", [&] { report.inputs = checkInputPolicies(); });
    return report;
}

} // namespace iblkit::stress
