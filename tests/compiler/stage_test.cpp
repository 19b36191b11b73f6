// The stage comes from the entry point's attributes and semantics unless given.
#include "compile_error.hpp"
#include "shader_stage.hpp"

#include <gtest/gtest.h>

namespace iblkit::compiler {
namespace {

ShaderStage stageOf(const std::string& source, const std::string& entry = "main") {
    return deduceStage(source, entry, "s.hlsl");
}

TEST(StageDeduction, AttributesAndSemanticsTellTheStage) {
    EXPECT_EQ(stageOf("[numthreads(8, 8, 1)]\nvoid main(uint3 id : SV_DispatchThreadID) {}"), ShaderStage::Compute);
    EXPECT_EQ(stageOf("float4 main(float4 p : SV_Position) : SV_Target {}"), ShaderStage::Fragment);
    EXPECT_EQ(stageOf("float4 main(float3 p : POSITION) : SV_Position {}"), ShaderStage::Vertex);
    EXPECT_EQ(stageOf("[maxvertexcount(3)]\nvoid main(triangle float4 p[3] : SV_Position) {}"), ShaderStage::Geometry);
    EXPECT_EQ(stageOf("[domain(\"tri\")]\n[outputcontrolpoints(3)]\nHS main(InputPatch<VS, 3> p) {}"),
              ShaderStage::TessControl);
    EXPECT_EQ(stageOf("[domain(\"tri\")]\nDS main(float3 uvw : SV_DomainLocation) {}"), ShaderStage::TessEvaluation);
    EXPECT_EQ(stageOf("[shader(\"pixel\")]\nfloat4 main() : COLOR {}"), ShaderStage::Fragment);
}

TEST(StageDeduction, PicksTheNamedEntryAmongSeveral) {
    const std::string source = "float4 VSMain(float3 p : POSITION) : SV_Position {}\n"
                               "[numthreads(4, 4, 1)] void CSMain(uint3 id : SV_DispatchThreadID) {}\n";
    EXPECT_EQ(stageOf(source, "VSMain"), ShaderStage::Vertex);
    EXPECT_EQ(stageOf(source, "CSMain"), ShaderStage::Compute);
}

TEST(StageDeduction, UnsupportedStageIsNamed) {
    try {
        stageOf("[shader(\"raygeneration\")]\nvoid main() {}");
        FAIL() << "expected CompileError";
    } catch (const CompileError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "s.hlsl: error: entry point 'main' is a raygeneration shader, an unsupported stage "
                  "(supported: vertex, hull, domain, geometry, pixel, compute)");
    }
}

std::string refusalOf(const std::string& source) {
    try {
        stageOf(source);
    } catch (const CompileError& error) {
        return error.what();
    }
    return "(a stage)";
}

// Before, a mesh shader without [shader("mesh")] was taken for compute ([numthreads]) and ended in
// glslang's parse error at its `out vertices` parameter.
TEST(StageDeduction, MeshAndAmplificationShadersAreRecognizedAndRefusedByName) {
    const std::string unsupported = ", an unsupported stage (supported: vertex, hull, domain, geometry, pixel, compute)";
    EXPECT_EQ(refusalOf("[outputtopology(\"triangle\")]\n[numthreads(32, 1, 1)]\n"
                        "void main(uint t : SV_GroupThreadID, out vertices V v[3], out indices uint3 i[1]) {}"),
              "s.hlsl: error: entry point 'main' is a mesh shader" + unsupported);
    EXPECT_EQ(refusalOf("[numthreads(32, 1, 1)]\nvoid main(out indices uint3 i[1]) {}"),
              "s.hlsl: error: entry point 'main' is a mesh shader" + unsupported);
    EXPECT_EQ(refusalOf("groupshared P p;\n[numthreads(32, 1, 1)]\nvoid main(uint i : SV_GroupIndex) { DispatchMesh(1, 1, 1, p); }"),
              "s.hlsl: error: entry point 'main' is an amplification shader" + unsupported);
    // A hull shader states [outputtopology] too.
    EXPECT_EQ(stageOf("[domain(\"tri\")]\n[outputtopology(\"triangle_cw\")]\n[outputcontrolpoints(3)]\nHS main(InputPatch<VS, 3> p) {}"),
              ShaderStage::TessControl);
}

TEST(StageDeduction, NoClueAsksForTheStage) {
    EXPECT_THROW(stageOf("void main() {}"), CompileError);
    EXPECT_THROW(stageOf("[numthreads(1,1,1)] void other() {}"), CompileError);
}

TEST(StageNames, ShortLongAndHlslNamesAreAccepted) {
    EXPECT_EQ(parseStageName("comp"), ShaderStage::Compute);
    EXPECT_EQ(parseStageName("pixel"), ShaderStage::Fragment);
    EXPECT_EQ(parseStageName("hull"), ShaderStage::TessControl);
    EXPECT_EQ(parseStageName("raygen"), std::nullopt);
}

} // namespace
} // namespace iblkit::compiler
