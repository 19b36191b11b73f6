// The probe kernels: PBR.fxh's functions one by one (PbrProbeCS) and the kit's LUT function
// (LutProbeCS), on a regular grid of arguments away from the documents' singular points (those
// are iblkit stress's).
#include "probe_bake.hpp"
#include "suite_run.hpp"

#include <fmt/core.h>

namespace iblkit::consistency {
namespace {

ProbeArguments regularArguments() {
    ProbeArguments arguments;
    const uint32_t sampleCounts[] = {1024, 4096, 65536};
    for (const float c : {0.1f, 0.3f, 0.5f, 0.7f, 0.9f})
        for (const float roughness : {0.25f, 0.5f, 0.75f, 1.f})
            for (const float c2 : {0.2f, 0.6f, 1.f})
                for (const float c3 : {0.1f, 0.5f, 0.9f}) {
                    const uint32_t index = uint32_t(arguments.values.size());
                    const uint32_t count = sampleCounts[index % 3];
                    arguments.values.emplace_back(c, roughness, c2, c3);
                    arguments.sampleIndices.emplace_back((index * 37u) % count, count);
                }
    return arguments;
}

} // namespace

void addProbeOutputs(SuiteRun& run) {
    auto arguments = regularArguments();
    addOutput(run, {"PbrProbeCS", fmt::format("D, G, F, the GGX sample, Hammersley, IntegrateBRDF at {} arguments",
                                              arguments.values.size()),
                    pbrProbeBounds()},
              {pbrProbeReference<float>(arguments), pbrProbeReference<double>(arguments)},
              [&](const PathProgram& program) { return gpuProbe(run.vulkan, program, arguments, kPbrProbeResults); },
              [&](const OpenGlForm& form) { return glProbe(run.gl, form, arguments, kPbrProbeResults); });
    arguments.sampleIndices.clear();
    for (auto& value : arguments.values) value.z = 1.f - value.x; // exact for these N.V
    addOutput(run, {"LutProbeCS", fmt::format("the quadrature LUT at {} arguments", arguments.values.size()),
                    lutProbeBounds()},
              {lutProbeReference<float>(arguments), lutProbeReference<double>(arguments)},
              [&](const PathProgram& program) { return gpuProbe(run.vulkan, program, arguments, kLutProbeResults); },
              [&](const OpenGlForm& form) { return glProbe(run.gl, form, arguments, kLutProbeResults); });
}

} // namespace iblkit::consistency
