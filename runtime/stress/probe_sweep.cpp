#include "probe_sweep.hpp"

#include "bake_settings.hpp"
#include "probe_bake.hpp"

#include <fmt/core.h>

#include <bit>
#include <cmath>
#include <limits>
#include <set>

namespace iblkit::stress {
namespace {

using consistency::ProbeArguments;

constexpr float kDenormal = std::numeric_limits<float>::denorm_min();
constexpr float kCosines[] = {0.f, kDenormal, 1e-7f, 1e-4f, 0.5f, 1.f - 1e-7f, 1.f};
constexpr float kRoughnesses[] = {0.f, kDenormal, 1e-4f, 0.01f, 0.5f, 1.f};
constexpr float kEdges[] = {0.f, kDenormal, 1e-7f, 0.5f, 1.f - 1e-7f, 1.f};

// Hammersley's (i, n): counts from 1 to 2^32 - 1, each at its first, second, middle and last point.
std::vector<glm::uvec2> sampleIndices() {
    std::vector<glm::uvec2> indices;
    for (const uint32_t n : {1u, 2u, 3u, 1024u, 65535u, 65536u, 1u << 20, 1u << 24, 0xFFFFFFFFu})
        for (const uint32_t i : std::set<uint32_t>{0u, std::min(1u, n - 1), n / 2, n - 1}) indices.emplace_back(i, n);
    return indices;
}

ProbeArguments pbrArguments() {
    const auto indices = sampleIndices();
    ProbeArguments arguments;
    for (const float c : kCosines)
        for (const float roughness : kRoughnesses)
            for (const float c2 : kEdges)
                for (const float c3 : kEdges) {
                    arguments.sampleIndices.push_back(indices[arguments.values.size() % indices.size()]);
                    arguments.values.emplace_back(c, roughness, c2, c3);
                }
    return arguments;
}

// (N.L, N.V, roughness, azimuth of V): both cosines and the roughness at their edges, the render's
// smallest roughness among them, V beside L and opposite it.
constexpr float kRenderRoughnesses[] = {0.f, kDenormal, 1e-4f, 0.01f, 0.02f, 0.05f, 0.5f, 1.f};
ProbeArguments bsdfArguments() {
    ProbeArguments arguments;
    for (const float cosL : kCosines)
        for (const float cosV : kCosines)
            for (const float roughness : kRenderRoughnesses)
                for (const float phi : {0.f, 3.14159265f}) arguments.values.emplace_back(cosL, cosV, roughness, phi);
    return arguments;
}

ProbeArguments lutArguments() {
    ProbeArguments arguments;
    for (const float ndotv : kCosines)
        for (const float roughness : kRoughnesses)
            arguments.values.emplace_back(ndotv, roughness, float(1.0 - double(ndotv)), 0.f);
    return arguments;
}

// The smallest arguments any bake passes: the LUT's first texel centre at its largest size, and
// the roughness of mip 1 of the largest cube (the prefilter kernels that call D).
constexpr float kSmallestLutArgument = 0.5f / float(bake::kMaxLutSize);
const float kSmallestMipRoughness = bake::roughnessOfMip(1, uint32_t(std::bit_width(bake::kMaxCubeSize)));

bool lutDomain(const glm::vec4& argument) { return argument.x >= kSmallestLutArgument && argument.y >= kSmallestLutArgument; }
bool anywhere(const glm::vec4&) { return true; }
bool prefilterDomain(const glm::vec4& argument) { return argument.y >= kSmallestMipRoughness; }
// The path tracer's functions, where iblkit render calls them: N.L and N.V above 0 (from the
// smallest normal float: GPUs flush denormals to 0) at the sphere grid's roughness. Its least,
// 0.02, is left out: there alpha² = 1.6e-7 is below float's spacing at 1, and D's
// (N.H)²(alpha² - 1) + 1 cancels across the lobe's core (docs/stability-notes.md).
constexpr float kSmallestJudgedRenderRoughness = 0.05f;
bool renderDomain(const glm::vec4& argument) {
    constexpr float smallest = std::numeric_limits<float>::min();
    return argument.x >= smallest && argument.y >= smallest && argument.z >= kSmallestJudgedRenderRoughness;
}
// The sample's roughness is the LUT's (the smaller); xi comes from Hammersley, whose xi.y < 1.
bool sampleDomain(const glm::vec4& argument) { return argument.y >= kSmallestLutArgument && argument.w < 1.f; }

// How each function's arguments read in the list of singular points.
std::string ofNdotvAndRoughness(const ProbeArguments& arguments, size_t i) {
    return fmt::format("c = {:g}, r = {:g}", arguments.values[i].x, arguments.values[i].y);
}
std::string ofSmith(const ProbeArguments& arguments, size_t i) {
    const auto& v = arguments.values[i];
    return fmt::format("N.L = {:g}, N.V = {:g}, r = {:g}", v.z, v.x, v.y);
}
std::string ofFresnel(const ProbeArguments& arguments, size_t i) { return fmt::format("cos = {:g}", arguments.values[i].w); }
std::string ofSample(const ProbeArguments& arguments, size_t i) {
    const auto& v = arguments.values[i];
    return fmt::format("xi = ({:g}, {:g}), normal {}, r = {:g}", v.z, v.w, i % 5, v.y);
}
std::string ofDirections(const ProbeArguments& arguments, size_t i) {
    const auto& v = arguments.values[i];
    return fmt::format("N.L = {:g}, N.V = {:g}, r = {:g}", v.x, v.y, v.z); // at any azimuth and metalness
}
std::string ofHammersley(const ProbeArguments& arguments, size_t i) {
    return fmt::format("i = {}, n = {}", arguments.sampleIndices[i].x, arguments.sampleIndices[i].y);
}

// A function's place in its probe's results, how its error is measured and where the bake calls
// it. Each bound is twice the largest error measured on lavapipe where the bake calls the
// function, rounded up, for each kind of path: the C++ float twin, the four Vulkan paths and
// OpenGL (why each is what it is: docs/stability.md). One bound for all, set by the float twin,
// left the GPU paths up to 5000 times the error they have.
enum class Probe { Pbr, Lut, Bsdf };

const char* kernelOf(Probe probe) {
    return probe == Probe::Pbr ? "PbrProbeCS" : probe == Probe::Lut ? "LutProbeCS" : "BsdfProbeCS";
}

struct ProbeFunction {
    const char* name;
    Probe probe;
    uint32_t first, count; // floats within one argument's results
    bool relative;
    double floatBound, vulkanBound, openGlBound;
    bool (*calledByBake)(const glm::vec4& argument);
    std::string (*describe)(const ProbeArguments& arguments, size_t index);
};
const ProbeFunction kFunctions[] = {
    {"DistributionGGX (D)", Probe::Pbr, 0, 1, true, 1e-6, 1.5e-7, 1.5e-7, prefilterDomain, ofNdotvAndRoughness},
    {"GeometrySmithForIBL (G)", Probe::Pbr, 1, 1, false, 2e-7, 2e-7, 2e-7, lutDomain, ofSmith},
    {"GeometrySchlickGGXForIBL (G1)", Probe::Pbr, 2, 1, false, 1e-7, 1e-7, 1e-7, lutDomain, ofNdotvAndRoughness},
    {"FresnelSchlick (F)", Probe::Pbr, 4, 3, false, 2.4e-7, 1.2e-7, 1.2e-7, anywhere, ofFresnel},
    // The float twin's 0.28: its inverse CDF loses alpha^4 below float's step at 1 (roughness
    // below 0.0156) and returns H = N; llvmpipe contracts it into an fma and stays 1e-4 off
    // (docs/stability-notes.md), as IntegrateBRDF then does (0.17 against 1.1e-2).
    {"ImportanceSampleGGX", Probe::Pbr, 8, 3, false, 0.56, 2e-4, 2e-4, sampleDomain, ofSample},
    {"Hammersley", Probe::Pbr, 12, 2, false, 4e-8, 4e-8, 4e-8, anywhere, ofHammersley},
    {"IntegrateBRDF (1024 samples)", Probe::Pbr, 14, 2, false, 0.35, 0.022, 0.022, lutDomain, ofNdotvAndRoughness},
    {"IntegrateBrdfQuadrature (the kit's LUT)", Probe::Lut, 0, 2, false, 3e-6, 3.1e-6, 2.9e-6, anywhere, ofNdotvAndRoughness},
    // The path tracer's, judged where iblkit render calls them (renderDomain). D's cancellation as
    // N.H nears 1 at roughness 0.05 (6e-2 on OpenGL, 2e-2 on Vulkan, 6e-2 in the float reference)
    // reaches the BRDF, the BSDF and every term that evaluates them; the BTDF and the GGX density
    // carry the float reference's 2.7e-3 where N.V is 1e-7, which the GPU paths do not have.
    {"BRDF", Probe::Bsdf, 0, 3, true, 0.13, 0.046, 0.13, renderDomain, ofDirections},
    {"D", Probe::Bsdf, 3, 1, true, 0.13, 0.046, 0.13, renderDomain, ofDirections},
    {"BTDF", Probe::Bsdf, 4, 3, true, 6e-3, 1.2e-5, 1.2e-5, renderDomain, ofDirections},
    {"G (direct light)", Probe::Bsdf, 7, 1, false, 2e-7, 2e-7, 2e-7, renderDomain, ofDirections},
    {"BSDF", Probe::Bsdf, 8, 4, true, 0.13, 0.046, 0.13, renderDomain, ofDirections},
    {"SampleCosineHemisphere", Probe::Bsdf, 12, 3, false, 6e-7, 6e-7, 6e-7, renderDomain, ofDirections},
    {"CosineHemispherePdf", Probe::Bsdf, 15, 1, false, 3e-8, 3e-8, 3e-8, renderDomain, ofDirections},
    {"SampleGGX", Probe::Bsdf, 16, 3, false, 2.1e-4, 5.4e-5, 5.4e-5, renderDomain, ofDirections},
    {"GgxHalfVectorPdf", Probe::Bsdf, 19, 1, true, 6e-3, 1.5e-7, 1.5e-7, renderDomain, ofDirections},
    {"PointLightTerm", Probe::Bsdf, 20, 3, true, 5e-5, 5e-5, 5e-5, renderDomain, ofDirections},
    {"Random", Probe::Bsdf, 23, 1, false, 0, 0, 0, anywhere, ofDirections}, // integer hashing, exact
    {"AreaLightTerm, DirectionalLightTerm", Probe::Bsdf, 24, 4, true, 8e-5, 5.2e-4, 5.2e-4, renderDomain, ofDirections},
};

const char* finiteness(double value) {
    return std::isnan(value) ? "NaN" : std::isinf(value) ? "Inf" : "finite";
}

double errorOf(double value, double reference, bool relative) {
    const double difference = std::abs(value - reference);
    if (!relative) return difference;
    const double scale = std::abs(reference);
    return scale >= double(std::numeric_limits<float>::min()) ? difference / scale : difference;
}

struct ProbeValues {
    std::vector<float> inFloat;
    std::vector<double> inDouble;
    uint32_t stride; // floats per argument
};

ProbeRow judge(const ProbeFunction& function, const ProbeArguments& arguments, const ProbeValues& references,
               const std::vector<float>& path, std::string pathName, bool isFloatReference) {
    ProbeRow row{kernelOf(function.probe), function.name, std::move(pathName)};
    row.relative = function.relative;
    row.bound = isFloatReference                              ? function.floatBound
                : row.path == consistency::openGlPathName() ? function.openGlBound
                                                              : function.vulkanBound;
    for (size_t a = 0; a < arguments.values.size(); ++a)
        for (uint32_t k = 0; k < function.count; ++k) {
            const size_t at = a * references.stride + function.first + k;
            const double inDouble = references.inDouble[at];
            ++row.values;
            if (!std::isfinite(inDouble)) { ++row.singularInMath; continue; }
            if (!std::isfinite(references.inFloat[at])) { ++row.singularInFloat; continue; }
            if (!std::isfinite(path[at])) { ++row.nonFinite; continue; }
            const double error = errorOf(path[at], inDouble, function.relative);
            auto& maxError = function.calledByBake(arguments.values[a]) ? row.maxError : row.maxErrorElsewhere;
            maxError = std::max(maxError, error);
        }
    if (isFloatReference) row.nonFinite = 0;
    row.passed = row.nonFinite == 0 && row.maxError <= row.bound;
    return row;
}

void recordSingularPoints(const ProbeFunction& function, const ProbeArguments& arguments, const ProbeValues& references,
                          std::vector<SingularPoint>& singular) {
    std::set<std::string> seen;
    for (size_t a = 0; a < arguments.values.size(); ++a)
        for (uint32_t k = 0; k < function.count; ++k) {
            const size_t at = a * references.stride + function.first + k;
            if (std::isfinite(references.inDouble[at]) && std::isfinite(references.inFloat[at])) continue;
            auto text = function.describe(arguments, a);
            if (!seen.insert(text).second) continue;
            singular.push_back({function.name, std::move(text), finiteness(references.inDouble[at]),
                                finiteness(references.inFloat[at]), function.calledByBake(arguments.values[a])});
        }
}

uint32_t resultsOf(Probe probe) {
    return probe == Probe::Pbr ? consistency::kPbrProbeResults
           : probe == Probe::Lut ? consistency::kLutProbeResults
                                 : consistency::kBsdfProbeResults;
}

template <typename T>
std::vector<T> referenceOf(Probe probe, const ProbeArguments& arguments) {
    return probe == Probe::Pbr ? consistency::pbrProbeReference<T>(arguments)
           : probe == Probe::Lut ? consistency::lutProbeReference<T>(arguments)
                                 : consistency::bsdfProbeReference<T>(arguments);
}

void sweepProbe(consistency::SuiteRun& run, const ProbeArguments& arguments, Probe probe, ProbeSweep& sweep) {
    const char* kernel = kernelOf(probe);
    const uint32_t results = resultsOf(probe);
    const ProbeValues references{referenceOf<float>(probe, arguments), referenceOf<double>(probe, arguments), results * 4};
    std::vector<std::pair<std::string, std::vector<float>>> paths{{"f. C++ reference, float", references.inFloat}};
    for (const auto path : consistency::kVulkanPaths)
        paths.emplace_back(consistency::pathName(path),
                           consistency::gpuProbe(run.vulkan, run.program(kernel, path), arguments, results));
    paths.emplace_back(consistency::openGlPathName(), consistency::glProbe(run.gl, run.openGl(kernel), arguments, results));
    for (const auto& function : kFunctions) {
        if (function.probe != probe) continue;
        for (size_t p = 0; p < paths.size(); ++p)
            sweep.rows.push_back(judge(function, arguments, references, paths[p].second, paths[p].first, p == 0));
        recordSingularPoints(function, arguments, references, sweep.singular);
    }
}

} // namespace

ProbeSweep sweepProbes(consistency::SuiteRun& run) {
    ProbeSweep sweep;
    const auto pbr = pbrArguments();
    const auto lut = lutArguments();
    const auto bsdf = bsdfArguments();
    sweep.pbrArguments = pbr.values.size();
    sweep.lutArguments = lut.values.size();
    sweep.bsdfArguments = bsdf.values.size();
    sweepProbe(run, pbr, Probe::Pbr, sweep);
    sweepProbe(run, lut, Probe::Lut, sweep);
    sweepProbe(run, bsdf, Probe::Bsdf, sweep);
    return sweep;
}

} // namespace iblkit::stress
