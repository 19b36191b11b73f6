// Bad input gives a precise "file:line:column: error:" message, with the include chain.
#include "compile_error.hpp"
#include "compiler.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

namespace iblkit::compiler {
namespace {

class CompileErrors : public ::testing::Test {
protected:
    std::string errorOf(const std::filesystem::path& source, const std::string& entry = "main", bool bounded = false) {
        CompileOptions options;
        options.source = source;
        options.entryPoint = entry;
        options.boundPreprocessing = bounded;
        options.includeDirs.push_back(folder.path() / "include");
        try {
            compileShader(options);
        } catch (const CompileError& error) {
            return error.what();
        }
        ADD_FAILURE() << "compiled without an error";
        return "";
    }
    testing::TempFolder folder;
};

constexpr const char* kValidBody = "[numthreads(1, 1, 1)]\nvoid main(uint3 id : SV_DispatchThreadID) {}\n";

TEST_F(CompileErrors, SyntaxErrorNamesFileLineAndColumn) {
    const auto source = folder.write("syntax.hlsl", "[numthreads(1, 1, 1)]\nvoid main()\n{\n    float x = undefinedThing;\n}\n");
    const auto message = errorOf(source);
    // The kit's words first, glslang's own after them.
    EXPECT_EQ(message, source.string() + ":4:15: error: 'undefinedThing' is not declared where it is used "
                                         "(glslang: 'undefinedThing' : unknown variable)")
        << message;
}

TEST_F(CompileErrors, ErrorInAnIncludeShowsTheIncludeChain) {
    folder.write("include/Common/Bad.fxh", "float broken()\n{\n    return nothere;\n}\n");
    folder.write("include/Outer.fxh", "#include \"Common/Bad.fxh\"\n");
    // The entry point calls the broken function: one it never reaches is dropped, as DXC drops it.
    const auto source = folder.write("main.hlsl", "// top\n#include \"Outer.fxh\"\n[numthreads(1, 1, 1)]\n"
                                                  "void main(uint3 id : SV_DispatchThreadID) { float b = broken(); }\n");
    const auto message = errorOf(source);
    const auto outer = (folder.path() / "include/Outer.fxh").string();
    const auto bad = (folder.path() / "include/Common/Bad.fxh").string();
    EXPECT_EQ(message, "In file included from " + source.string() + ":2:\nIn file included from " + outer + ":1:\n" +
                           bad + ":3:12: error: 'nothere' is not declared where it is used (glslang: 'nothere' : unknown variable)")
        << message;
}

TEST_F(CompileErrors, MissingIncludeNamesTheDirectiveAndHeader) {
    const auto source = folder.write("missing.hlsl", std::string("#include \"Nowhere.fxh\"\n") + kValidBody);
    const auto message = errorOf(source);
    EXPECT_EQ(message.rfind(source.string() + ":1:", 0), 0u) << message;
    EXPECT_NE(message.find("Nowhere.fxh"), std::string::npos) << message;
}

TEST_F(CompileErrors, UnknownEntryPoint) {
    const auto source = folder.write("entry.hlsl", kValidBody);
    EXPECT_EQ(errorOf(source, "CSMain"), source.string() + ": error: entry point 'CSMain' is not defined");
}

TEST_F(CompileErrors, MissingSourceFile) {
    const auto source = folder.path() / "absent.hlsl";
    EXPECT_EQ(errorOf(source), source.string() + ": error: no such file");
}

TEST_F(CompileErrors, TwoResourcesInOneRegister) {
    const auto source = folder.write("clash.hlsl", R"(
RWTexture2D<float4> A : register(u1);
RWTexture2D<float4> B : register(u1);
[numthreads(1, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) { A[id.xy] = 1; B[id.xy] = 2; }
)");
    EXPECT_EQ(errorOf(source), source.string() + ": error: register u1, space0 is used by both 'A' and 'B'");
}

// Both hung the compiler, memory growing without end; the cycle is now named where it closes.
TEST_F(CompileErrors, AFileThatIncludesItselfIsAnIncludeCycle) {
    const auto source = folder.write("self.hlsl", std::string("#include \"self.hlsl\"\n") + kValidBody);
    EXPECT_EQ(errorOf(source), source.string() + ":1: error: #include cycle: " + source.string() + " → " +
                                   source.string() + " (a file that includes itself, directly or through others, "
                                                     "with no include guard)");
}

TEST_F(CompileErrors, TwoFilesThatIncludeEachOtherAreAnIncludeCycle) {
    const auto a = folder.write("a.hlsl", std::string("#include \"b.hlsl\"\n") + kValidBody);
    const auto b = folder.write("b.hlsl", "// b\n#include \"a.hlsl\"\n");
    const auto message = errorOf(a);
    EXPECT_EQ(message.rfind(b.string() + ":2: error: #include cycle: " + a.string() + " → " + b.string() + " → " +
                                a.string(), 0),
              0u) << message;
}

// An include guard ends a cycle at its second entry, as in C: such sources compile.
TEST_F(CompileErrors, AGuardedIncludeCycleCompiles) {
    folder.write("include/ga.fxh", "#ifndef GA\n#define GA\n#include \"gb.fxh\"\n#endif\n");
    folder.write("include/gb.fxh", "#ifndef GB\n#define GB\n#include \"ga.fxh\"\nfloat f() { return 1; }\n#endif\n");
    CompileOptions options;
    options.source = folder.write("guarded.hlsl", "#include \"ga.fxh\"\nRWStructuredBuffer<float> O;\n"
                                                  "[numthreads(1, 1, 1)] void main() { O[0] = f(); }\n");
    options.includeDirs.push_back(folder.path() / "include");
    EXPECT_NO_THROW(compileShader(options));
}

// Each macro doubles the one before: X39 stands for 2^39 tokens, which glslang expanded until
// it was stopped. Bounded, the preprocessing ends at its CPU limit (5 s) with an error.
TEST_F(CompileErrors, AMacroThatExpandsWithoutBoundEndsAtTheLimit) {
    std::string text = "#define X0 1 +\n";
    for (int i = 1; i < 40; ++i) text += "#define X" + std::to_string(i) + " X" + std::to_string(i - 1) + " X" + std::to_string(i - 1) + "\n";
    text += "RWStructuredBuffer<float> O;\n[numthreads(1, 1, 1)] void main() { O[0] = X39 1; }\n";
    const auto source = folder.write("doubling.hlsl", text);
    const auto message = errorOf(source, "main", true);
    EXPECT_EQ(message.rfind(source.string() + ": error: glslang used more than 5 s of CPU time", 0), 0u) << message;
    EXPECT_NE(message.find("a macro that expands without bound"), std::string::npos) << message;
}

// A syntax error in the entry's own signature was reported as "entry point 'main' is not
// defined", with no place; glslang's first parse error is reported instead.
TEST_F(CompileErrors, ASyntaxErrorInTheEntrysSignatureIsReportedWhereItIs) {
    const auto source = folder.write("signature.hlsl", "RWStructuredBuffer<float> O;\n[numthreads(1, 1, 1)]\n"
                                                       "void main( : SV_DispatchThreadID) { O[0] = 1; }\n");
    EXPECT_EQ(errorOf(source), source.string() + ":3:33: error: a syntax error: ')' expected here (glslang: ')' : Expected)");
    const auto missing = folder.write("missing.hlsl", "RWStructuredBuffer<float> O;\n[numthreads(1, 1, 1)] void CSMain() { O[0] = 1; }\n");
    EXPECT_EQ(errorOf(missing), missing.string() + ": error: entry point 'main' is not defined");
}

// "-D =5" was reported at -1:1:1, and "-D FOO-BAR" passed with a warning.
TEST_F(CompileErrors, ADefineWhoseNameIsNoIdentifierIsRefused) {
    const auto source = folder.write("ok.hlsl", kValidBody);
    for (const auto& [name, value] : std::vector<std::pair<std::string, std::string>>{{"", "5"}, {"FOO-BAR", ""}, {"1X", "2"}}) {
        CompileOptions options;
        options.source = source;
        options.defines[name] = value;
        try {
            compileShader(options);
            ADD_FAILURE() << "'" << name << "' was taken";
        } catch (const CompileError& error) {
            EXPECT_NE(std::string(error.what()).find("'" + name + "' is not a macro name"), std::string::npos) << error.what();
        }
    }
}

// glslang 11 dereferences a null pointer on an unnamed entry-point parameter (found by fuzzing
// the compile entry; tests/fuzz/corpus/hlsl/unnamed_parameter.hlsl replays it): bounded, it is an error.
TEST_F(CompileErrors, ASourceGlslangCrashesOnIsAnErrorNotACrash) {
    const auto source = folder.write("unnamed.hlsl", "float4 main(float4 : SV_Position) : SV_Target { return p; }\n");
    const auto message = errorOf(source, "main", true);
    EXPECT_EQ(message.rfind(source.string() + ": error: glslang crashed (Segmentation fault) on this source", 0), 0u) << message;
}

TEST_F(CompileErrors, BoundedPreprocessingReportsTheSameErrors) {
    const auto source = folder.write("syntax.hlsl", "#include \"Nowhere.fxh\"\n");
    EXPECT_EQ(errorOf(source, "main", true), errorOf(source));
}

// With the stage given, glslang alone ended a missing entry point in "resource binding failed".
TEST_F(CompileErrors, AMissingEntryPointIsNamedWhenTheStageIsGiven) {
    const auto source = folder.write("compute.hlsl", kValidBody);
    CompileOptions options;
    options.source = source;
    options.entryPoint = "CSMain";
    options.stage = ShaderStage::Compute;
    try {
        compileShader(options);
        FAIL() << "compiled";
    } catch (const CompileError& error) {
        EXPECT_EQ(std::string(error.what()), source.string() + ": error: entry point 'CSMain' is not defined");
    }
}

// asfloat(uint4x4(...)): glslang's integer matrix failed SPIRV-Tools' legalization with a message
// about an OpTypeMatrix the user never wrote.
TEST_F(CompileErrors, AnIntegerMatrixIsNamedWithTheWayAround) {
    const auto source = folder.write("matrix.hlsl", "RWStructuredBuffer<uint4> Bits;\nRWStructuredBuffer<float> Out;\n"
                                                    "[numthreads(1, 1, 1)]\nvoid main() {\n"
                                                    "    float4x4 f = asfloat(uint4x4(Bits[0], Bits[1], Bits[2], Bits[3]));\n"
                                                    "    Out[0] = f[1][2];\n}\n");
    const auto message = errorOf(source);
    EXPECT_EQ(message.rfind(source.string() + ": error: an integer matrix (uint4x4, int3x3, ...) has no SPIR-V type for "
                                              "Vulkan, and glslang keeps it as one: hold its rows in vectors",
                            0),
              0u)
        << message;
}

} // namespace
} // namespace iblkit::compiler
