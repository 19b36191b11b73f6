// A constant buffer Direct3D packs where a Vulkan uniform block cannot is refused by name; the
// packings both can hold compile.
#include "compile_error.hpp"
#include "compiler.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

namespace iblkit::compiler {
namespace {

std::string packingErrorOf(const std::string& members, const std::string& prelude = "") {
    testing::TempFolder folder;
    CompileOptions options;
    options.source = folder.write("packing.hlsl", prelude + "cbuffer Params : register(b0) { " + members +
                                                      " };\nRWStructuredBuffer<float> Out : register(u0);\n"
                                                      "[numthreads(1, 1, 1)] void main() { Out[0] = last; }\n");
    try {
        compileShader(options);
    } catch (const CompileError& error) {
        const std::string message = error.what();
        return message.substr(message.find("error: "));
    }
    return "(compiled)";
}

TEST(ConstantBufferPacking, AMemberInTheLastRegisterOfAnArrayIsRefusedByName) {
    EXPECT_EQ(packingErrorOf("float weights[3]; float last;"),
              "error: constant buffer 'Params', member 'last': Direct3D packs it at byte 36, into the last register of the "
              "array, struct or matrix before it, where a Vulkan uniform block cannot place it (the SPIR-V has it at byte "
              "48), so the application's constant data would be read at the wrong place: start it on a register of its own "
              "(pad the member before it to a float4) or move it before that member");
    EXPECT_NE(packingErrorOf("S s; float last;", "struct S { float3 a; };\n").find("member 'last': Direct3D packs it at byte 12"),
              std::string::npos);
    EXPECT_NE(packingErrorOf("float3x3 m; float last;").find("member 'last': Direct3D packs it at byte 44"), std::string::npos);
}

TEST(ConstantBufferPacking, PackingsBothLayoutsHoldCompile) {
    for (const std::string members : {"float3 a; float last;", "float a; float2 b; float last;", "float2 a; float3 b; float last;",
                                      "float4 weights[3]; float last;", "float4x4 m; float last;", "float a; float3 last;",
                                      // packoffset places a member where both layouts agree (DirectXTK's effects).
                                      "float3 a : packoffset(c0); float last : packoffset(c1.x);",
                                      "float w[3] : packoffset(c0); float last : packoffset(c3);"})
        EXPECT_EQ(packingErrorOf(members), "(compiled)") << members;
}

} // namespace
} // namespace iblkit::compiler
