// `iblkit compile` and `iblkit compile-all` as a user runs them: every output written on
// success; on bad input one clear message, a non-zero exit, and no file written or damaged.
#include "read_file.hpp"
#include "run_process.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <unistd.h>

namespace iblkit::testing {
namespace {

namespace fs = std::filesystem;

class Cli : public ::testing::Test {
protected:

    ProcessResult iblkit(std::vector<std::string> arguments) const {
        arguments.insert(arguments.begin(), IBLKIT_EXECUTABLE);
        return runProcess(arguments);
    }
    std::string at(const std::string& name) const { return (out / name).string(); }
    size_t filesInOut() const { return std::distance(fs::directory_iterator(out), fs::directory_iterator()); }

    // A failed run: non-zero exit, one line on stderr holding `expected`, nothing written.
    void expectFailure(const std::vector<std::string>& arguments, const std::string& expected) const {
        const auto result = iblkit(arguments);
        EXPECT_NE(result.exitCode, 0);
        EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_EQ(filesInOut(), 0u) << "a failed run wrote files";
    }

    TempFolder scratch;
    const fs::path& out = scratch.path();
};

TEST_F(Cli, CompileWritesAllSevenFiles) {
    const auto result = iblkit({"compile", "hlsl/document/PrecomputedBrdfCS.hlsl", "-o", at("lut.spv"), "--glsl", at("lut.glsl"),
                                "--essl", at("lut.essl"), "--msl", at("lut.metal"), "--hlsl", at("lut.hlsl"),
                                "--reflect", at("lut.json"), "-MD", "-MF", at("lut.d")});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    for (const char* name : {"lut.spv", "lut.glsl", "lut.essl", "lut.metal", "lut.hlsl", "lut.json", "lut.d"})
        EXPECT_GT(fs::file_size(out / name), 0u) << name;
    EXPECT_EQ(filesInOut(), 7u) << "no temporaries are left";
    EXPECT_EQ(readFile(out / "lut.d"), at("lut.spv") + ": hlsl/document/PrecomputedBrdfCS.hlsl \\\n  hlsl/document/Common/PBR.fxh\n");
}

TEST_F(Cli, FlagsReachTheCompiler) {
    const auto result = iblkit({"compile", "hlsl/document/PrecomputedBrdfCS.hlsl", "-o", at("lut.spv"), "-Os", "--strip",
                                "-DSAMPLE_COUNT=64", "-I", "hlsl", "--image-format", "Precomputed=rg16f",
                                "--binding-shift", "u=7", "--binding-shift", "b=0", "--reflect", at("lut.json")});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const auto json = readFile(out / "lut.json");
    EXPECT_NE(json.find("\"binding\": 7"), std::string::npos) << json;
    EXPECT_NE(json.find("\"format\": \"rg16f\""), std::string::npos) << json;
}

// Each -D takes one value, before or after the source; the shader computes with both (A * 10 + B
// is 25 only when A is 2 and B is 5), and without B it does not compile.
TEST_F(Cli, RepeatableFlagsTakeOneValueEachWhereverTheSourceStands) {
    std::ofstream(out / "defines.hlsl") << "RWStructuredBuffer<uint> Out;\n[numthreads(1, 1, 1)]\nvoid main() { Out[0] = A * 10 + B; }\n";
    const auto result = iblkit({"compile", "-D", "A=2", at("defines.hlsl"), "-D", "B=5", "-o", at("defines.spv"), "--glsl",
                                at("defines.glsl")});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const auto glsl = readFile(out / "defines.glsl");
    EXPECT_NE(glsl.find("Out_1._data[0] = 25u;"), std::string::npos) << glsl;
    const auto withoutB = iblkit({"compile", "-D", "A=2", at("defines.hlsl"), "-o", at("defines.spv")});
    EXPECT_NE(withoutB.exitCode, 0);
    EXPECT_NE(withoutB.err.find("'B' : unknown variable"), std::string::npos) << withoutB.err;
}

TEST_F(Cli, SameInputAndFlagsGiveByteIdenticalOutputs) {
    const auto compileInto = [&](const std::string& prefix) {
        const auto result = iblkit({"compile", "hlsl/document/PrefilterSpecularCS.hlsl", "-o", at(prefix + ".spv"), "-O",
                                    "--glsl", at(prefix + ".glsl"), "--essl", at(prefix + ".essl"), "--msl",
                                    at(prefix + ".metal"), "--hlsl", at(prefix + ".hlsl"), "--reflect", at(prefix + ".json")});
        ASSERT_EQ(result.exitCode, 0) << result.err;
    };
    compileInto("first");
    compileInto("second");
    for (const char* extension : {".spv", ".glsl", ".essl", ".metal", ".hlsl", ".json"})
        EXPECT_TRUE(readFile(out / (std::string("first") + extension)) == readFile(out / (std::string("second") + extension)))
            << extension;
}

TEST_F(Cli, SyntaxError) {
    const auto source = (out / "bad.hlsl").string();
    std::ofstream(source) << "[numthreads(1,1,1)]\nvoid main() { float x = ; }\n";
    const auto result = iblkit({"compile", source, "-o", at("bad.spv"), "--glsl", at("bad.glsl")});
    EXPECT_NE(result.exitCode, 0);
    EXPECT_EQ(result.err.rfind(source + ":2:", 0), 0u) << result.err;
    EXPECT_NE(result.err.find(": error: "), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(out / "bad.spv"));
    EXPECT_FALSE(fs::exists(out / "bad.glsl"));
}

TEST_F(Cli, MissingInclude) {
    const auto source = (out / "inc.hlsl").string();
    std::ofstream(source) << "#include \"Common/Missing.fxh\"\n[numthreads(1,1,1)]\nvoid main() {}\n";
    const auto result = iblkit({"compile", source, "-o", at("inc.spv")});
    EXPECT_NE(result.exitCode, 0);
    EXPECT_EQ(result.err.rfind(source + ":1:", 0), 0u) << result.err;
    EXPECT_NE(result.err.find("Common/Missing.fxh"), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(out / "inc.spv"));
}

TEST_F(Cli, UnknownEntryPoint) {
    expectFailure({"compile", "hlsl/document/PrecomputedBrdfCS.hlsl", "-o", at("x.spv"), "-E", "CSMain"},
                  "hlsl/document/PrecomputedBrdfCS.hlsl: error: entry point 'CSMain' is not defined");
}

TEST_F(Cli, UnsupportedStage) {
    expectFailure({"compile", "hlsl/document/PrecomputedBrdfCS.hlsl", "-o", at("x.spv"), "-S", "raygen"},
                  "error: unsupported stage 'raygen'");
}

TEST_F(Cli, MissingSourceFile) {
    expectFailure({"compile", "hlsl/NoSuchShader.hlsl", "-o", at("x.spv")}, "hlsl/NoSuchShader.hlsl: error: no such file");
}

// The suite's sampled kernels loop over the samples in one dispatch: past 65535 llvmpipe would end
// the loop early and the report would compare truncated sums.
TEST_F(Cli, ConsistencySamplesPastTheLoopLimitAreRefused) {
    expectFailure({"consistency", "--samples", "65536"}, "--samples 65536 is out of range (1 to 65535)");
    expectFailure({"consistency", "--samples", "0"}, "--samples 0 is out of range (1 to 65535)");
}

TEST_F(Cli, UnknownFlag) {
    expectFailure({"compile", "hlsl/document/PrecomputedBrdfCS.hlsl", "-o", at("x.spv"), "--fast-math"}, "iblkit: error:");
}

// It said "A subcommand is required".
TEST_F(Cli, AnUnknownCommandIsNamedWithTheCommands) {
    const auto result = iblkit({"frobnicate"});
    EXPECT_EQ(result.exitCode, 2);
    EXPECT_EQ(result.err, "iblkit: error: unknown command 'frobnicate' (commands: compile, compile-all, devices, run, "
                          "consistency, stress, bake, batch, plan, bench, lut-fit, porting, render, render-report, shading)\n");
}

TEST_F(Cli, UnwritableOutputPathLeavesEveryOtherOutputUnwritten) {
    const auto result = iblkit({"compile", "hlsl/document/PrecomputedBrdfCS.hlsl", "-o", at("lut.spv"), "--glsl",
                                at("no/such/folder/lut.glsl")});
    EXPECT_NE(result.exitCode, 0);
    EXPECT_NE(result.err.find("lut.glsl: error: cannot write the file: no such directory"), std::string::npos) << result.err;
    EXPECT_EQ(filesInOut(), 0u);
}

TEST_F(Cli, AFailedRunNeverDamagesAGoodOutput) {
    std::ofstream(out / "lut.spv") << "GOOD";
    const auto result = iblkit({"compile", "hlsl/document/PrecomputedBrdfCS.hlsl", "-o", at("lut.spv"), "-E", "nothere"});
    EXPECT_NE(result.exitCode, 0);
    EXPECT_EQ(readFile(out / "lut.spv"), "GOOD");
    EXPECT_EQ(filesInOut(), 1u);
}

// `compile ok.hlsl -o ok.hlsl` replaced the source with SPIR-V. An output that is an input (the
// source, an included file, through any path or link) or that two outputs share is refused, and
// the source stays as it was.
TEST_F(Cli, AnOutputThatIsAnInputOrAnotherOutputIsRefused) {
    std::ofstream(out / "ok.hlsl") << "#include \"inc.fxh\"\nRWStructuredBuffer<float> O;\n"
                                      "[numthreads(1, 1, 1)] void main() { O[0] = Two(); }\n";
    std::ofstream(out / "inc.fxh") << "float Two() { return 2.f; }\n";
    fs::create_symlink(out / "ok.hlsl", out / "link.spv");
    const auto source = readFile(out / "ok.hlsl");
    const std::pair<std::vector<std::string>, std::string> cases[] = {
        {{"-o", at("ok.hlsl")}, "ok.hlsl: error: this output is also an input of the command"},
        {{"-o", at("link.spv")}, "link.spv: error: this output is also an input of the command ('" + at("ok.hlsl") + "')"},
        {{"-o", at("x.spv"), "--glsl", at("inc.fxh")}, "inc.fxh: error: this output is also an input of the command"},
        {{"-o", at("x.spv"), "--glsl", at("x.spv")}, "x.spv: error: two outputs of the command are this one file"},
        {{"-o", at("x.spv"), "--reflect", out.string() + "/./x.spv"}, "two outputs of the command are this one file"},
    };
    for (const auto& [flags, expected] : cases) {
        std::vector<std::string> arguments{"compile", at("ok.hlsl")};
        arguments.insert(arguments.end(), flags.begin(), flags.end());
        const auto result = iblkit(arguments);
        EXPECT_EQ(result.exitCode, 1) << result.err;
        EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
        EXPECT_EQ(readFile(out / "ok.hlsl"), source);
        EXPECT_FALSE(fs::exists(out / "x.spv"));
    }
}

// Every form of every shader but the ESSL of the two chunked accumulators and the two Monte Carlo
// references, which read and write an rg32f or rgba32f image: ESSL 3.10 cannot, so that form is
// refused with its reason and the rest written.
TEST_F(Cli, CompileAllPrintsOneLinePerShaderAndWritesEveryForm) {
    const auto result = iblkit({"compile-all", "hlsl/shaders.json", "-o", at("all")});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const char* shaders[] = {"PrecomputedBrdfCS",      "PrefilterSpecularCS", "PrecomputedBrdfChunkCS",
                             "PrefilterSpecularChunkCS", "EquirectToCubeCS",  "DownsampleCubeCS",
                             "ShProjectCS",            "IrradianceCubeCS",    "PreviewCS",
                             "ClusterCubeCS",          "PrefilterConvolutionCS", "SkyCubeCS",
                             "BrdfLutQuadratureCS",    "PrefilterFilteredCS", "PrefilterTableCS",
                             "BrdfLutGridCS",          "BrdfLutResampleCS",   "PrefilterPyramidCS",
                             "PrefilterRingCS",        "BrdfLutFitCS",        "PbrProbeCS",
                             "BsdfProbeCS",            "LutProbeCS",          "RenderReferenceCS",
                             "RenderReferenceSplitSumMaterialCS", "SplitSumSpheresCS"};
    EXPECT_EQ(std::count(result.out.begin(), result.out.end(), '\n'), std::size(shaders)) << result.out;
    EXPECT_EQ(result.out.rfind("PrecomputedBrdfCS ", 0), 0u) << result.out;
    for (const char* name : shaders) EXPECT_NE(result.out.find(std::string(name) + " "), std::string::npos) << name;
    const std::set<std::string> refusedEssl = {"PrecomputedBrdfChunkCS", "PrefilterSpecularChunkCS", "RenderReferenceCS",
                                               "RenderReferenceSplitSumMaterialCS"};
    for (const char* name : shaders)
        for (const std::string extension : {".spv", ".glsl", ".essl", ".metal", ".hlsl", ".json"})
            EXPECT_EQ(fs::exists(out / "all" / (name + extension)), !(extension == ".essl" && refusedEssl.contains(name)))
                << name << extension;
    EXPECT_NE(result.err.find("hlsl/PrecomputedBrdfChunkCS.hlsl: error: essl cannot express the shader: storage image "
                              "'Accumulated' (rg32f) is both read and written"),
              std::string::npos)
        << result.err;
}

TEST_F(Cli, CompileWritesTheFormsItCanAndExitsWith4ForARefusedOne) {
    std::ofstream(at("wave.hlsl")) << "RWStructuredBuffer<float> Out : register(u0);\n[numthreads(32, 1, 1)]\n"
                                      "void main(uint3 id : SV_DispatchThreadID) { Out[id.x] = WaveActiveSum(1.0); }\n";
    const auto result = iblkit({"compile", at("wave.hlsl"), "-o", at("wave.spv"), "--glsl", at("wave.glsl"), "--vulkan-glsl",
                                at("wave.vk.glsl"), "--hlsl", at("wave.out.hlsl")});
    EXPECT_EQ(result.exitCode, 4) << result.err;
    EXPECT_NE(result.err.find("glsl cannot express the shader: wave operations"), std::string::npos) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_TRUE(fs::exists(at("wave.spv")));
    EXPECT_TRUE(fs::exists(at("wave.vk.glsl")));
    EXPECT_TRUE(fs::exists(at("wave.out.hlsl")));
    EXPECT_FALSE(fs::exists(at("wave.glsl")));
}

TEST_F(Cli, CompileAllRejectsAnUnknownForm) {
    expectFailure({"compile-all", "hlsl/shaders.json", "-o", at("all"), "--only", "glsl,spirv-asm"},
                  "--only: unknown form 'spirv-asm'");
}

// Names become output files: two alike overwrote each other, "../x" and "/abs" wrote outside
// -o, "" wrote a hidden ".spv"; an unknown key was taken silently. Each is refused, before any file.
TEST_F(Cli, CompileAllRefusesManifestNamesThatAreNotPlainFileNamesAndUnknownKeys) {
    const std::string shader = fs::absolute("hlsl/document/PrecomputedBrdfCS.hlsl").string();
    const auto manifest = [&](const std::string& entries) {
        std::ofstream(out / "m.json") << R"({"shaders": [)" + entries + "]}";
        return (out / "m.json").string();
    };
    const auto entry = [&](const std::string& name, const std::string& extra = "") {
        return R"({"name": ")" + name + R"(", "source": ")" + shader + R"(", "image_formats": {"Precomputed": "rg16f"})" +
               extra + "}";
    };
    const std::pair<std::string, std::string> cases[] = {
        {entry("A") + ", " + entry("A"), "two shaders are named 'A'"},
        {entry("../escape"), "shader name '../escape' is not a plain file name"},
        {entry("/abs/name"), "shader name '/abs/name' is not a plain file name"},
        {entry(""), "shader name '' is not a plain file name"},
        {entry(".hidden"), "shader name '.hidden' is not a plain file name"},
        {entry("A", R"(, "defnes": {"N": "1"})"), "shader A has an unknown key 'defnes'"},
    };
    for (const auto& [entries, expected] : cases) {
        const auto result = iblkit({"compile-all", manifest(entries), "-o", at("all")});
        EXPECT_EQ(result.exitCode, 1) << entries;
        EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
        EXPECT_FALSE(fs::exists(out / "all")) << entries;
    }
    EXPECT_FALSE(fs::exists(out.parent_path() / "escape.spv"));
}

TEST_F(Cli, LutFitWritesTheCommittedInclude) {
    const auto result = iblkit({"lut-fit", "-o", at("BrdfLutFit.fxh")});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_EQ(readFile(at("BrdfLutFit.fxh")), readFile("hlsl/Common/BrdfLutFit.fxh"));
}

// `porting --out` its own corpus manifest wrote the page over it, after the whole corpus ran (a
// copy of the corpus here: the check must never be able to destroy the real one).
TEST(ReportCommands, AnOutputThatIsAnInputIsRefusedBeforeAnyWork) {
    TempFolder folder;
    fs::copy("hlsl/porting", folder.path() / "corpus", fs::copy_options::recursive);
    const auto manifest = folder.path() / "corpus" / "corpus.json";
    const auto before = readFile(manifest);
    const auto result = runProcess({IBLKIT_EXECUTABLE, "porting", "--corpus", (folder.path() / "corpus").string(), "--out",
                                    manifest.string(), "-q"});
    EXPECT_NE(result.exitCode, 0);
    EXPECT_NE(result.err.find("this output is also an input of the command"), std::string::npos) << result.err;
    EXPECT_EQ(result.out.find("PASS"), std::string::npos) << "refused after the corpus ran";
    EXPECT_EQ(readFile(manifest), before);
}

// `stress --out missing/x.md` failed only after a minute of work: each report-writing command
// now refuses a report it could not write before it starts.
TEST(ReportCommands, AnOutputThatCannotBeWrittenIsRefusedBeforeAnyWork) {
    TempFolder folder;
    const auto missing = folder.path() / "missing" / "report.md";
    for (const char* command : {"stress", "consistency", "porting", "lut-fit"}) {
        const auto result = runProcess({IBLKIT_EXECUTABLE, command, "--out", missing.string()});
        EXPECT_NE(result.exitCode, 0) << command;
        EXPECT_NE(result.err.find("--out " + missing.string() + ": the folder " + missing.parent_path().string() + " does not exist"),
                  std::string::npos)
            << command << ": " << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        const auto toFolder = runProcess({IBLKIT_EXECUTABLE, command, "--out", folder.path().string()});
        EXPECT_NE(toFolder.err.find(": is a folder, not a file"), std::string::npos) << command << ": " << toFolder.err;
        // A system file in a folder that takes no new file (root may write to /proc, which has
        // none to give): once "No such file or directory" after the work.
        const auto system = runProcess({IBLKIT_EXECUTABLE, command, "--out", "/proc/version"});
        EXPECT_NE(system.exitCode, 0) << command;
        EXPECT_NE(system.err.find("--out /proc/version: "), std::string::npos) << command << ": " << system.err;
        EXPECT_EQ(std::count(system.err.begin(), system.err.end(), '\n'), 1) << system.err;
    }
}

} // namespace
} // namespace iblkit::testing
