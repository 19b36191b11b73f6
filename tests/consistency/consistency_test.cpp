// Every path of every kernel computes what the C++ reference computes (PreviewCS: what path a
// computes), within the bounds measured and explained in docs/consistency.md; deliberately
// broken shaders do not.
#include "consistency_suite.hpp"
#include "kernels/kernel_table.hpp"
#include "shader_paths.hpp"
#include "markdown_table.hpp"
#include "read_file.hpp"
#include "temp_folder.hpp"
#include "vulkan_context.hpp"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace iblkit::consistency {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> allPathNames() {
    std::vector<std::string> names;
    for (const auto path : kVulkanPaths) names.emplace_back(pathName(path));
    names.emplace_back(openGlPathName());
    return names;
}

// Small enough for the broken variants, which fail long before the sizes matter.
SuiteOptions testSizes(SuiteOptions options) {
    options.lutSizes = {32};
    options.quadratureLutSize = 32;
    options.prefilterSize = 16;
    return options;
}

// With validation on: anything the layer says fails the test.
std::vector<ConsistencyRow> run(const SuiteOptions& options) {
    auto log = std::make_shared<vulkan::ValidationLog>();
    std::vector<ConsistencyRow> rows;
    {
        const vulkan::VulkanContext context({"", true, log});
        rows = runConsistency(context, options).rows;
    }
    for (const auto& message : log->messages()) ADD_FAILURE() << "validation: " << message;
    return rows;
}

// Whether a row is of `path` (PreviewCS's path a row, its reference, says so after the name).
bool isOnPath(const ConsistencyRow& row, std::string_view path) { return row.path.rfind(path, 0) == 0; }

// A report row's cells that do not depend on the machine: kernel, output, path, the two bounds and
// the verdict (the measured errors do).
using RowShape = std::vector<std::string>;

RowShape shapeOf(const ConsistencyRow& row) {
    const auto bounds = [&](double max, double rms) { return row.isReference ? std::string("—") : fmt::format("{:.1e} / {:.1e}", max, rms); };
    std::string verdict = row.passed ? "yes" : "**no**";
    if (!row.knownIssue.empty()) verdict = row.passed ? "**yes, though known to diverge**" : "no, known (see the bounds)";
    return {row.kernel, row.output, row.path, bounds(row.bounds.maxVsFloat, row.bounds.rmsVsFloat),
            bounds(row.bounds.maxVsDouble, row.bounds.rmsVsDouble), row.isReference ? std::string("—") : verdict};
}

// The same cells of every row of the committed report's table.
std::vector<RowShape> committedShapes(const std::string& report) {
    std::vector<RowShape> shapes;
    std::istringstream stream(report);
    for (std::string line; std::getline(stream, line);) {
        const auto cells = testing::tableCells(line);
        if (cells.size() == 13 && cells[0] != "kernel" && !cells[0].starts_with("---"))
            shapes.push_back({cells[0], cells[1], cells[2], cells[10], cells[11], cells[12]});
    }
    return shapes;
}

// The whole suite, as `iblkit consistency` runs it for docs/consistency.md (about 50 s).
TEST(Consistency, EveryPathIsWithinItsBoundsForEveryOutput) {
    const auto rows = run(defaultSuiteOptions());
    ASSERT_EQ(rows.size(), 39u * 6u + 4u * 5u + 3u)
        << "LUT 512² and 32², the quadrature LUT, the quadrature grid's nodes and resampling, the polynomial LUT, four prefilter roughnesses, the chunked LUT and prefilter, the sky, the panorama, the mip chain, the "
           "harmonics, the irradiance cube, the energy pyramid and its convolution by N·L and by G1, by both the manifest's walk and the bake's (SOURCE_TEXELS_IN_PYRAMID), the filtered, table and pyramid "
           "prefilters at four roughnesses, the pyramid's ring at the two of them wide enough for it, the three probes: the float "
           "reference and five paths each; the preview, both Monte Carlo references and the split-sum spheres: path a "
           "as the reference and four paths; the forward pass drawn on three";
    EXPECT_EQ(std::count_if(rows.begin(), rows.end(), [](const auto& row) { return row.path == openGlPathName(); }), 43)
        << "path d runs on OpenGL for every output";
    for (const auto& kernel : kernels::kernelTable())
        for (const auto& path : allPathNames())
            EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [&](const auto& row) {
                return row.kernel == kernel.name && isOnPath(row, path);
            })) << kernel.name << " has no row on path " << path;
    for (const auto& row : rows) {
        if (row.isReference) continue;
        EXPECT_TRUE(row.asExpected()) << row.output << " / " << row.path << " (" << row.knownIssue << "): max " << row.vsFloat.maxAbsolute << " vs float, "
                                << row.vsDouble.maxAbsolute << " vs double; RMS " << row.vsFloat.rms << ", "
                                << row.vsDouble.rms;
        EXPECT_EQ(row.vsFloat.nonFinite, 0u) << row.output << " / " << row.path;
    }
    // docs/consistency.md is this run's report, committed: the same rows, bounds and verdicts (the
    // errors depend on the machine). A report left stale by a change to the suite is caught here.
    const std::string report = testing::readFile("docs/consistency.md");
    ASSERT_FALSE(report.empty()) << "docs/consistency.md is missing; run: iblkit consistency --out docs/consistency.md";
    EXPECT_NE(report.find("Made by `iblkit consistency --out docs/consistency.md`"), std::string::npos);
    EXPECT_NE(report.find(boundsRationale()), std::string::npos) << "the report's bounds are not the suite's";
    std::vector<RowShape> live;
    for (const auto& row : rows) live.push_back(shapeOf(row));
    const auto committed = committedShapes(report);
    EXPECT_EQ(committed.size(), live.size()) << "regenerate: iblkit consistency --out docs/consistency.md";
    for (size_t i = 0; i < std::min(committed.size(), live.size()); ++i)
        EXPECT_EQ(committed[i], live[i]) << "row " << i << " of docs/consistency.md is stale: iblkit consistency --out docs/consistency.md";
}

// Outside a source tree `iblkit consistency` said only "hlsl/shaders.json: no such file"; it now
// runs the copy of hlsl/ built into the program.
TEST(ConsistencyOptions, WithoutAManifestOnDiskTheBuiltInShadersServe) {
    const auto options = defaultSuiteOptions("no/such/folder/shaders.json", 16);
    ASSERT_EQ(options.shaders.size(), kernels::kernelTable().size() + 2) << "every kernel, the bake's convolution walk and the forward pass";
    EXPECT_TRUE(options.shaders.contains(kForwardPassShader));
    EXPECT_TRUE(options.shaders.contains(kConvolutionInPyramidShader));
    for (const auto& [name, shader] : options.shaders) {
        ASSERT_TRUE(shader.sourceText.has_value()) << name;
        EXPECT_FALSE(shader.virtualFiles.empty()) << name;
    }
    EXPECT_NO_THROW(compileForPath(ShaderPath::Glslang, options.shaders.at("PbrProbeCS")));
}

// A copy of hlsl/ with one change, compiled through the same paths.
class BrokenVariant : public ::testing::Test {
protected:
    SuiteOptions broken(const std::string& file, const std::string& faithful, const std::string& brokenText) {
        fs::copy("hlsl", scratch.path() / "hlsl", fs::copy_options::recursive);
        const auto path = scratch.path() / "hlsl" / file;
        std::string source = testing::readFile(path);
        const auto at = source.find(faithful);
        EXPECT_NE(at, std::string::npos) << "the faithful text to break is no longer in " << file;
        source.replace(at, faithful.size(), brokenText);
        std::ofstream(path) << source;
        auto options = testSizes(defaultSuiteOptions((scratch.path() / "hlsl" / "shaders.json").string()));
        options.roughnesses = {0.25f, 0.5f};
        return options;
    }

    // Runs the suite on the broken copy for `kernels` alone (what the break touches): each of them
    // fails on every path, and no other kernel's rows are there.
    static void expectEveryPathFails(SuiteOptions options, const std::set<std::string>& kernels) {
        options.kernels = kernels;
        const auto rows = run(options);
        for (const auto& kernel : kernels) {
            size_t failedPaths = 0, paths = 0;
            for (const auto& row : rows)
                if (!row.isReference && row.kernel == kernel) {
                    ++paths;
                    failedPaths += !row.passed;
                }
            EXPECT_GT(paths, 0u) << kernel;
            EXPECT_EQ(failedPaths, paths) << "a broken " << kernel << " passed the comparison on some path";
        }
        for (const auto& row : rows) EXPECT_TRUE(kernels.contains(row.kernel)) << row.kernel << " ran, though not asked for";
    }

    testing::TempFolder scratch;
};

// The classic port's bug: the vertex shader's y not turned down the image. The drawn spheres are
// mirrored in each cell, and every path of the forward pass fails against the computed image.
TEST_F(BrokenVariant, AnUnflippedYFailsTheForwardPass) {
    expectEveryPathFails(broken("ForwardSpheres.hlsl", "float2( input.Position.x, -input.Position.y )",
                                "float2( input.Position.x, input.Position.y )"),
                         {kForwardPassShader});
}

TEST_F(BrokenVariant, KFromDirectLightingFailsTheLut) {
    expectEveryPathFails(broken("document/Common/PBR.fxh", "float k = ( a * a ) / 2.f;", "float k = ( ( a + 1.f ) * ( a + 1.f ) ) / 8.f;"),
                         {"PrecomputedBrdfCS", "PrecomputedBrdfChunkCS"});
}

// The path tracer's port: each mistake the document invites fails the probe on every path.
TEST_F(BrokenVariant, KForImageBasedLightingFailsThePathTracersG) {
    expectEveryPathFails(broken("document/Common/Bsdf.fxh", "float k = ( Roughness + 1.f ) * ( Roughness + 1.f ) / 8.f;",
                                 "float k = Roughness * Roughness / 2.f;"), {"BsdfProbeCS"});
}

TEST_F(BrokenVariant, InvertedEtaFailsTheBtdf) {
    expectEveryPathFails(broken("document/Common/Bsdf.fxh",
                                 "float EtaI = LightOutside ? 1.f : X.Eta;\n    float EtaO = LightOutside ? X.Eta : 1.f;",
                                 "float EtaI = LightOutside ? X.Eta : 1.f;\n    float EtaO = LightOutside ? 1.f : X.Eta;"), {"BsdfProbeCS"});
}

TEST_F(BrokenVariant, TheDocumentsHalfVectorSignFailsTheBtdf) {
    expectEveryPathFails(broken("document/Common/Bsdf.fxh", "float3 H = -normalize( EtaI * L + EtaO * V );",
                                 "float3 H = normalize( EtaI * L + EtaO * V );"), {"BsdfProbeCS"});
}

TEST_F(BrokenVariant, TransposedTangentFrameFailsThePrefilter) {
    expectEveryPathFails(broken("document/Common/PBR.fxh", "return normalize( mul( h, toWorld ) );", "return normalize( mul( toWorld, h ) );"), {"PrefilterSpecularCS", "PrefilterSpecularChunkCS"});
}

TEST_F(BrokenVariant, SwappedCubeFaceFailsThePrefilter) {
    expectEveryPathFails(broken("document/PrefilterSpecularCS.hlsl", "normal = float3( uv.x, 1.f, -uv.y );", "normal = float3( uv.x, -1.f, uv.y );"), {"PrefilterSpecularCS"});
}

// The visible arc's length from llvmpipe's atan (2e-5 off) instead of the quadrature's own: both
// LUT kernels that integrate fail.
TEST_F(BrokenVariant, ImpreciseArcFailsTheQuadratureLut) {
    expectEveryPathFails(broken("Common/BrdfQuadrature.fxh", "S[0] = 2.f * PreciseAtan( tanHalfArc );", "S[0] = 2.f * atan( tanHalfArc );"), {"BrdfLutQuadratureCS", "BrdfLutGridCS"});
}

// The grid's N.V at u³ instead of s (2 - s), s = u³: nodes where the interpolation does not look
// for them.
TEST_F(BrokenVariant, CubeRootGridFailsTheGridNodes) {
    expectEveryPathFails(broken("Common/LutGrid.fxh", "return float2( s * ( 2.f - s ), rest * rest );", "return float2( s, rest );"), {"BrdfLutGridCS"});
}

// The edge node repeated past the grid's last node instead of extrapolated (the first interval
// holds no texel of a 32² LUT: it ends at N.V = 1/31³).
TEST_F(BrokenVariant, RepeatedEdgeNodeFailsTheResampling) {
    expectEveryPathFails(broken("BrdfLutResampleCS.hlsl", "if ( cell == last - 1 ) after = 3.f * end - 3.f * start + before;",
                                 "if ( cell == last - 1 ) after = end;"), {"BrdfLutResampleCS"});
}

// The kit's cube geometry: +Y's direction swapped for -Y's in Cube.fxh.
TEST_F(BrokenVariant, SwappedCubeFaceFailsEveryKernelOfCubeFxh) {
    expectEveryPathFails(broken("Common/Cube.fxh", "direction = float3( uv.x, 1.f, -uv.y );", "direction = float3( uv.x, -1.f, uv.y );"),
                         {"PrefilterSpecularChunkCS", "EquirectToCubeCS", "ShProjectCS", "IrradianceCubeCS", "ClusterCubeCS",
                          "PrefilterConvolutionCS", "SkyCubeCS", "PrefilterFilteredCS", "PrefilterTableCS", "PrefilterPyramidCS"});
}

// The light's mean direction divided by the block's solid angle instead of the light's weight.
TEST_F(BrokenVariant, LightMeanOverTheWrongWeightFailsTheConvolution) {
    expectEveryPathFails(broken("PrefilterConvolutionCS.hlsl",
                                 "float3 light = weighted.w > 0.f ? weighted.xyz * ( 1.f / weighted.w ) : extent;",
                                 "float3 light = weighted.w > 0.f ? weighted.xyz * ( 1.f / geometry.w ) : extent;"),
                         {"PrefilterConvolutionCS"});
}

// HLSL's log is the natural one: a port that writes it for log2 reads every sample 0.69 times as
// far up the chain.
TEST_F(BrokenVariant, NaturalLogLodFailsTheFilteredPrefilter) {
    expectEveryPathFails(broken("PrefilterFilteredCS.hlsl", "log2( texelsPerSample )", "log( texelsPerSample )"), {"PrefilterFilteredCS"});
}

TEST_F(BrokenVariant, UnweightedSamplesFailTheTablePrefilter) {
    expectEveryPathFails(broken("PrefilterTableCS.hlsl", ".rgb * entry.z;", ".rgb;"), {"PrefilterTableCS"});
}

// The lod shift for a texel's smaller solid angle towards the corners, turned the wrong way.
TEST_F(BrokenVariant, CornerShiftTheWrongWayFailsThePyramidPrefilter) {
    expectEveryPathFails(broken("PrefilterPyramidCS.hlsl", "float lodShift = -0.5f * log2(", "float lodShift = 0.5f * log2("), {"PrefilterPyramidCS"});
}

// The ring's reads at the complement of its angle from the normal: sine and cosine swapped.
TEST_F(BrokenVariant, RingAtTheComplementaryAngleFailsTheRingPrefilter) {
    expectEveryPathFails(broken("PrefilterRingCS.hlsl", "float3 toLight = Ring.z * normal + sinAngle * (",
                                 "float3 toLight = sinAngle * normal + Ring.z * ("), {"PrefilterRingCS"});
}

// The polynomial's N.V axis at the square root instead of the fourth root it was fitted in.
TEST_F(BrokenVariant, SquareRootAxisFailsThePolynomialLut) {
    expectEveryPathFails(broken("BrdfLutFitCS.hlsl", "Chebyshev( sqrt( sqrt( ndotv ) ), tu );", "Chebyshev( sqrt( ndotv ), tu );"), {"BrdfLutFitCS"});
}

// A wrong 2x2 weight: texel (1, 0) read twice, (1, 1) never.
TEST_F(BrokenVariant, WrongTexelFailsTheMipChain) {
    expectEveryPathFails(broken("DownsampleCubeCS.hlsl", "Source.Load( int4( corner + int2( 1, 1 ), DTid.z, SourceMip ) )",
                                 "Source.Load( int4( corner + int2( 1, 0 ), DTid.z, SourceMip ) )"), {"DownsampleCubeCS"});
}

} // namespace
} // namespace iblkit::consistency
