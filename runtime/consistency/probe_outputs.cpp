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

// (cos θ_L, cos θ_V, roughness, φ_V) about N = +Z: grazing to head on, at two azimuths.
ProbeArguments bsdfArguments() {
    ProbeArguments arguments;
    for (const float cosL : {0.15f, 0.6f, 0.95f})
        for (const float cosV : {0.3f, 0.8f})
            for (const float roughness : {0.2f, 0.6f, 1.f})
                for (const float phiV : {1.f, 4.f}) arguments.values.emplace_back(cosL, cosV, roughness, phiV);
    return arguments;
}

} // namespace

void addProbeOutputs(SuiteRun& run) {
    auto arguments = regularArguments();
    addOutput(run, {"PbrProbeCS", fmt::format("D, G, F, the GGX sample, Hammersley, IntegrateBRDF at {} arguments",
                                              arguments.values.size()),
                    pbrProbeBounds()},
              [&] { return References{pbrProbeReference<float>(arguments), pbrProbeReference<double>(arguments)}; },
              [&](const PathProgram& program) { return gpuProbe(run.vulkan, program, arguments, kPbrProbeResults); },
              [&](const OpenGlForm& form) { return glProbe(run.gl, form, arguments, kPbrProbeResults); });
    arguments.sampleIndices.clear();
    for (auto& value : arguments.values) value.z = 1.f - value.x; // exact for these N.V
    addOutput(run, {"LutProbeCS", fmt::format("the quadrature LUT at {} arguments", arguments.values.size()),
                    lutProbeBounds()},
              [&] { return References{lutProbeReference<float>(arguments), lutProbeReference<double>(arguments)}; },
              [&](const PathProgram& program) { return gpuProbe(run.vulkan, program, arguments, kLutProbeResults); },
              [&](const OpenGlForm& form) { return glProbe(run.gl, form, arguments, kLutProbeResults); });
    const auto bsdf = bsdfArguments();
    addOutput(run, {"BsdfProbeCS", fmt::format("the path tracer's BRDF, BTDF, BSDF, D, G, sampling and lights at {} "
                                               "arguments", bsdf.values.size()),
                    bsdfProbeBounds()},
              [&] { return References{bsdfProbeReference<float>(bsdf), bsdfProbeReference<double>(bsdf)}; },
              [&](const PathProgram& program) { return gpuProbe(run.vulkan, program, bsdf, kBsdfProbeResults); },
              [&](const OpenGlForm& form) { return glProbe(run.gl, form, bsdf, kBsdfProbeResults); });
}

} // namespace iblkit::consistency
