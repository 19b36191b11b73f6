// The analytic properties of the documents' functions, on the C++ reference and on the GPU.
#include "compiler.hpp"
#include "compute_program.hpp"
#include "error_stats.hpp"
#include "gpu_bake.hpp"
#include "pbr.hpp"
#include "reference_bake.hpp"
#include "shader_manifest.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace iblkit::consistency {
namespace {

constexpr float kRoughnesses[] = {0.05f, 0.1f, 0.25f, 0.5f, 0.75f, 1.0f};

// 2π ∫ D(cos θ) cos θ sin θ dθ over [0, π/2] by composite Simpson in s, θ = (π/2)s⁴: the nodes
// crowd near θ = 0, where D peaks at low roughness.
double distributionIntegral(double roughness, int intervals) {
    const double halfPi = reference::PI<double> / 2;
    const auto integrand = [&](double s) {
        const double theta = halfPi * s * s * s * s, dtheta = halfPi * 4 * s * s * s;
        return reference::DistributionGGX<double>(std::cos(theta), roughness) * std::cos(theta) * std::sin(theta) * dtheta;
    };
    double sum = integrand(0) + integrand(1);
    for (int i = 1; i < intervals; ++i) sum += (i % 2 ? 4 : 2) * integrand(double(i) / intervals);
    return 2 * reference::PI<double> * sum / (3.0 * intervals);
}

// A context with validation; anything the layer says fails the test.
class Analytic : public ::testing::Test {
protected:
    void TearDown() override {
        context.reset();
        for (const auto& message : log->messages()) ADD_FAILURE() << "validation: " << message;
    }

    // Runs a test shader that includes Common/PBR.fxh and writes `count` floats to Output.
    std::vector<float> runShader(const std::string& source, uint32_t count, uint32_t threads) {
        compiler::CompileOptions options;
        options.source = "hlsl/analytic_test.hlsl";
        options.sourceText = source;
        options.includeDirs = {"hlsl", "hlsl/document"};
        const auto shader = compiler::compileShader(options);
        vulkan::ComputeProgram program(*context, shader.spirv, shader.reflection);
        vulkan::Buffer output(*context, count * 4, vk::BufferUsageFlagBits::eStorageBuffer, "Output");
        program.bind("Output", output);
        program.dispatchThreads(*context, {threads, 1, 1});
        const auto bytes = output.read();
        std::vector<float> values(count);
        std::memcpy(values.data(), bytes.data(), count * 4);
        return values;
    }

    static PathProgram seedProgram(const std::string& name, std::map<std::string, std::string> defines,
                                   std::map<std::string, std::string> formats = {}) {
        auto options = compiler::manifestShaderOptions("hlsl/shaders.json", name);
        for (auto& [key, value] : defines) options.defines[key] = value;
        for (auto& [key, value] : formats) options.imageFormats[key] = value;
        return compileForPath(ShaderPath::Glslang, options);
    }

    std::shared_ptr<vulkan::ValidationLog> log = std::make_shared<vulkan::ValidationLog>();
    std::optional<vulkan::VulkanContext> context{std::in_place, vulkan::ContextOptions{"", true, log}};
};

TEST_F(Analytic, DistributionIsNormalized) {
    // ∫ D(h) (n·h) dω = 2π ∫₀¹ D(t) t dt over the hemisphere, t = cos θ.
    for (float roughness : kRoughnesses)
        EXPECT_NEAR(distributionIntegral(roughness, 1 << 16), 1.0, 1e-9) << "reference, roughness " << roughness;
    // The same integral on the GPU with PBR.fxh's DistributionGGX: a midpoint rule in θ = (π/2)s⁴,
    // whose nodes crowd near θ = 0, where D peaks at low roughness.
    const auto values = runShader(R"(
#include "Common/PBR.fxh"
RWStructuredBuffer<float> Output;
static const float Roughnesses[6] = {0.05f, 0.1f, 0.25f, 0.5f, 0.75f, 1.0f};
[numthreads(6, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    const uint N = 16384;
    float sum = 0;
    for (uint i = 0; i < N; ++i) {
        float s = (i + 0.5f) / N;
        float theta = 0.5f * PI * s * s * s * s;
        float dtheta = 0.5f * PI * 4 * s * s * s / N;
        sum += DistributionGGX(cos(theta), Roughnesses[id.x]) * cos(theta) * sin(theta) * dtheta;
    }
    Output[id.x] = 2 * PI * sum;
}
)", 6, 6);
    // Measured: within 8e-5 at roughness 0.05 (a float sum of 16384 terms over the sharpest
    // lobe), 3.3e-5 at 0.1, 2.1e-6 above. Bound twice the worst; a wrong D (alpha = roughness
    // instead of roughness², a lost π) is off by a factor.
    for (size_t i = 0; i < 6; ++i) EXPECT_NEAR(values[i], 1.0, 1.6e-4) << "GPU, roughness " << kRoughnesses[i];
}

TEST_F(Analytic, LutAtRoughnessZeroIsSchlick) {
    for (double ndotv : {0.01, 0.1, 0.3, 0.5, 0.9, 1.0}) {
        const auto scaleBias = reference::IntegrateBRDF<double>(ndotv, 0.0, 1024);
        const double fc = std::pow(1 - ndotv, 5);
        EXPECT_NEAR(scaleBias.x, 1 - fc, 1e-12) << ndotv;
        EXPECT_NEAR(scaleBias.y, fc, 1e-12) << ndotv;
    }
    const auto values = runShader(R"(
#include "Common/PBR.fxh"
RWStructuredBuffer<float> Output;
[numthreads(32, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float ndotv = (id.x + 0.5f) / 32;
    float2 scaleBias = IntegrateBRDF(ndotv, 0.0f);
    Output[id.x * 2] = scaleBias.x;
    Output[id.x * 2 + 1] = scaleBias.y;
}
)", 64, 32);
    double worst = 0;
    for (uint32_t i = 0; i < 32; ++i) {
        const double ndotv = (i + 0.5) / 32, fc = std::pow(1 - ndotv, 5);
        worst = std::max({worst, std::fabs(values[2 * i] - (1 - fc)), std::fabs(values[2 * i + 1] - fc)});
    }
    // Measured 1.28e-5: llvmpipe's pow(x, 5); the bound is twice that, rounded up.
    EXPECT_LT(worst, 3e-5);
}

TEST_F(Analytic, ScalePlusBiasNeverExceedsOne) {
    const auto gpu = gpuBrdfLut(*context, seedProgram("PrecomputedBrdfCS", {}, {{"Precomputed", "rg32f"}}), 32);
    const auto ref = reference::referenceBrdfLut<double>(32, 1024);
    double gpuMax = 0, refMax = 0;
    for (size_t i = 0; i < gpu.size(); i += 2) {
        gpuMax = std::max(gpuMax, double(gpu[i]) + gpu[i + 1]);
        refMax = std::max(refMax, ref[i] + ref[i + 1]);
    }
    // Measured: 0.999998 on the GPU, 0.9999966 in double. No slack: the split sum reflects at
    // most the energy that arrives.
    EXPECT_LE(gpuMax, 1.0);
    EXPECT_LE(refMax, 1.0);
}

TEST_F(Analytic, WhiteFurnace) {
    const reference::CubeEnvironment white(16, std::vector<float>(6 * 16 * 16 * 4, 2.5f));
    for (float roughness : {0.0f, 0.25f, 0.5f, 1.0f}) {
        const auto gpu = gpuPrefilter(*context, seedProgram("PrefilterSpecularCS", {}), white, roughness, 16);
        const auto ref = reference::referencePrefilter<double>(white, roughness, 16, 1024);
        double gpuWorst = 0, refWorst = 0;
        for (size_t i = 0; i < gpu.size(); ++i) {
            const double expected = i % 4 == 3 ? 0.0 : 2.5;
            gpuWorst = std::max(gpuWorst, std::fabs(gpu[i] - expected));
            refWorst = std::max(refWorst, std::fabs(ref[i] - expected));
        }
        // Measured: at most 1.2e-6 on the GPU (four float ULPs of 2.5, from the weighted sum
        // divided by the total weight) and 7e-15 in double; bounds twice those, rounded up.
        EXPECT_LE(gpuWorst, 2.5e-6) << "roughness " << roughness;
        EXPECT_LE(refWorst, 1e-13) << "roughness " << roughness;
    }
}

TEST_F(Analytic, ErrorFallsAsSamplesGrow) {
    // Ground truth: the double reference with 2^18 samples on an 8² LUT. Its own error is about
    // its distance to 2^16 samples, which must be small beside what it judges.
    const auto truth = reference::referenceBrdfLut<double>(8, 1u << 18);
    const auto coarser = reference::referenceBrdfLut<double>(8, 1u << 16);
    const double truthError = measureError(std::vector<float>(coarser.begin(), coarser.end()), truth).rms;
    std::vector<double> rms;
    for (uint32_t samples : {64u, 256u, 1024u, 4096u}) {
        const auto gpu = gpuBrdfLut(*context, seedProgram("PrecomputedBrdfCS", {{"SAMPLE_COUNT", std::to_string(samples)}},
                                                          {{"Precomputed", "rg32f"}}), 8);
        rms.push_back(measureError(gpu, truth).rms);
    }
    EXPECT_LT(truthError, rms.back() / 4) << "the ground truth is not converged enough to judge 4096 samples";
    // Measured on 16²: each 4x more samples divides the RMS error by 2.4 to 2.6 (Hammersley points
    // converge faster than random ones' 2x); demand at least 1.8x per step.
    for (size_t i = 1; i < rms.size(); ++i) EXPECT_LT(rms[i], rms[i - 1] / 1.8) << "step " << i;
}

} // namespace
} // namespace iblkit::consistency
