// `iblkit devices` and `iblkit run` as a user runs them: the documented examples pass with
// validation on, a failed expectation is reported with its worst value, and each broken run
// file gets one line naming the problem and a non-zero exit.
#include "run_process.hpp"
#include "temp_folder.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace iblkit::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class RunCli : public ::testing::Test {
protected:

    // A documented example, with its paths made to work from the scratch folder.
    json example(const std::string& name) const {
        std::ifstream stream("docs/examples/" + name);
        json run = json::parse(stream);
        const auto absolute = [](const json& path) { return fs::absolute(fs::path("docs/examples") / path.get<std::string>()).lexically_normal(); };
        for (const char* stage : {"vertex", "pixel"})
            if (run.contains(stage)) run[stage]["shader"] = absolute(run[stage]["shader"]);
        if (run.contains("shader")) run["shader"] = absolute(run["shader"]);
        run["include"] = json::array({fs::absolute("hlsl").string(), fs::absolute("hlsl/document").string()});
        for (auto& [resource, file] : run["save"].items()) file = (folder / file.get<std::string>()).string();
        return run;
    }
    json fastPrefilter() const {
        json run = example("prefilter_white_furnace.run.json");
        run["defines"]["SAMPLE_COUNT"] = "16";
        run.erase("save");
        return run;
    }
    ProcessResult iblkitRun(const json& run, std::vector<std::string> environment = {}) const {
        const auto path = folder / "test.run.json";
        std::ofstream(path) << run.dump(2);
        return runProcess({IBLKIT_EXECUTABLE, "run", path.string(), "--validate"}, environment);
    }
    void expectError(const json& run, const std::string& expected) const {
        const auto result = iblkitRun(run);
        EXPECT_NE(result.exitCode, 0);
        EXPECT_NE(result.err.find(expected), std::string::npos) << result.err << result.out;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    }

    TempFolder scratch;
    const fs::path& folder = scratch.path();
};

TEST_F(RunCli, DevicesListsLavapipeAsTheDefault) {
    const auto result = runProcess({IBLKIT_EXECUTABLE, "devices"});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_NE(result.out.find("* 0  llvmpipe"), std::string::npos) << result.out;
}

TEST_F(RunCli, WithoutAVulkanDriverOneLineSaysWhatToInstall) {
    for (const char* command : {"devices", "run"}) {
        std::vector<std::string> arguments = {IBLKIT_EXECUTABLE, command};
        if (std::string(command) == "run") arguments.push_back("docs/examples/brdf_lut.run.json");
        const auto result = runProcess(arguments, {"VK_DRIVER_FILES=/nonexistent/icd.json", "VK_ICD_FILENAMES=/nonexistent/icd.json"});
        EXPECT_NE(result.exitCode, 0) << command;
        EXPECT_EQ(result.err, "no Vulkan device found: install Mesa's lavapipe (Debian package mesa-vulkan-drivers) "
                              "or a GPU driver\n")
            << command;
    }
}

// Every documented example on every path of --api all: each passes on each, and the report gives
// each path's largest difference from Vulkan's for every value the shaders write.
TEST_F(RunCli, EveryExamplePassesOnEveryPathAndTheirDifferencesAreReported) {
    for (const auto& entry : fs::directory_iterator("docs/examples")) {
        const auto name = entry.path().filename().string();
        if (!name.ends_with(".run.json")) continue;
        auto run = example(name);
        run.erase("save");
        const auto path = folder / "test.run.json";
        std::ofstream(path) << run.dump(2);
        const auto result = runProcess({IBLKIT_EXECUTABLE, "run", path.string(), "--api", "all"});
        EXPECT_EQ(result.exitCode, 0) << name << "\n" << result.out << result.err;
        for (const char* line : {"PASS round trip", "PASS cross-API", "largest difference"})
            EXPECT_NE(result.out.find(line), std::string::npos) << name << " lacks '" << line << "':\n" << result.out;
        EXPECT_EQ(result.out.find("FAIL"), std::string::npos) << name << "\n" << result.out;
    }
}

TEST_F(RunCli, ThePrefilterExamplePassesAndSavesItsOutput) {
    const auto result = iblkitRun(example("prefilter_white_furnace.run.json"));
    ASSERT_EQ(result.exitCode, 0) << result.out << result.err;
    EXPECT_NE(result.out.find("PASS Prefiltered: 24576 values within abs 0.0001"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("1 of 1 expectations passed"), std::string::npos);
    EXPECT_EQ(fs::file_size(folder / "prefiltered.npy"), 128u + 24576u * 4u);
}

TEST_F(RunCli, TheLutExamplePassesAndSavesItsOutput) {
    const auto result = iblkitRun(example("brdf_lut.run.json"));
    ASSERT_EQ(result.exitCode, 0) << result.out << result.err;
    EXPECT_NE(result.out.find("PASS Precomputed: 524288 values within [0, 1]"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("dispatch 64x64x1 groups"), std::string::npos) << result.out;
    EXPECT_TRUE(fs::exists(folder / "brdf_lut.npy"));
}

// Run as it is committed, from its own folder's relative paths, with the validation layer on.
TEST_F(RunCli, ThePbrFunctionsExamplePassesWithinItsTolerance) {
    const auto result = runProcess({IBLKIT_EXECUTABLE, "run", "docs/examples/pbr_functions.run.json", "--validate"});
    ASSERT_EQ(result.exitCode, 0) << result.out << result.err;
    EXPECT_NE(result.out.find("PASS Results: 32 values within abs 1e-05"), std::string::npos) << result.out;
}

TEST_F(RunCli, AFailedExpectationNamesItsWorstValueAndExitsWith3) {
    auto run = fastPrefilter();
    run["expect"][0]["fill"] = {1, 1, 1, 0.5};
    const auto result = iblkitRun(run);
    EXPECT_EQ(result.exitCode, 3) << result.err;
    EXPECT_NE(result.out.find("FAIL Prefiltered: 24576 values within abs 0.0001; 6144 outside, worst at mip 0 layer 0 (0, 0) "
                              "channel 3: expected 0.5, got 0"),
              std::string::npos)
        << result.out;
    EXPECT_NE(result.out.find("0 of 1 expectations passed"), std::string::npos);
}

// RWTexture2D<float3> is rgba32f; glslang wrote its texels with 3 components, which the
// validation layer rejects (VUID-RuntimeSpirv-OpImageWrite-07112) and which left alpha 0.
TEST_F(RunCli, AThreeComponentStorageImageIsWrittenWithFourUnderValidation) {
    std::ofstream(folder / "colour.hlsl") << "RWTexture2D<float3> Colour : register(u0);\n[numthreads(2, 2, 1)]\n"
                                             "void main(uint3 id : SV_DispatchThreadID) { Colour[id.xy] = float3(id.x, id.y, 7); }\n";
    const json run = {
        {"shader", (folder / "colour.hlsl").string()},
        {"resources", {{"Colour", {{"kind", "storage_image"}, {"dim", "2d"}, {"format", "R32G32B32A32_SFLOAT"}, {"size", {2, 2}}}}}},
        {"dispatch", {{"threads", {2, 2, 1}}}},
        {"expect", {{{"resource", "Colour"}, {"values", {0, 0, 7, 1, 1, 0, 7, 1, 0, 1, 7, 1, 1, 1, 7, 1}}}}}};
    const auto result = iblkitRun(run);
    EXPECT_EQ(result.exitCode, 0) << result.out << result.err;
    EXPECT_NE(result.out.find("PASS Colour: 16 values exactly"), std::string::npos) << result.out;
}

// glslang emitted HLSL's exclusive prefix operations as inclusive scans: every lane's own value
// was added (3 per lane here, where all must be 0).
TEST_F(RunCli, WavePrefixOperationsLeaveTheirOwnLaneOut) {
    std::ofstream(folder / "prefix.hlsl")
        << "RWStructuredBuffer<uint> Out : register(u0);\n[numthreads(64, 1, 1)]\n"
           "void main(uint3 id : SV_DispatchThreadID) {\n    uint lane = WaveGetLaneIndex();\n"
           "    Out[id.x] = (WavePrefixSum(1u) - lane) + (WavePrefixCountBits(true) - lane) + "
           "(uint(WavePrefixProduct(2.0)) - (1u << lane));\n}\n";
    const json run = {{"shader", (folder / "prefix.hlsl").string()},
                      {"resources", {{"Out", {{"kind", "buffer"}, {"type", "uint"}, {"count", 64}}}}},
                      {"dispatch", {{"threads", {64, 1, 1}}}},
                      {"expect", {{{"resource", "Out"}, {"fill", 0}}}}};
    const auto result = iblkitRun(run);
    EXPECT_EQ(result.exitCode, 0) << result.out << result.err;
    EXPECT_NE(result.out.find("PASS Out: 64 values exactly"), std::string::npos) << result.out;
}

// Integers past 2^24 were once rounded through a float: 4294967294 went in as 2^32 and came
// back as 0, and 16777217 compared equal to 16777216.
class IntegerRuns : public RunCli {
protected:
    json copyRun(const json& input, const json& expected) const {
        std::ofstream(folder / "copy.hlsl") << "StructuredBuffer<uint> In : register(t0);\n"
                                               "RWStructuredBuffer<uint> Out : register(u0);\n"
                                               "[numthreads(2, 1, 1)] void main(uint3 id : SV_DispatchThreadID) "
                                               "{ Out[id.x] = In[id.x] + 1; }\n";
        return {{"shader", (folder / "copy.hlsl").string()},
                {"resources", {{"In", {{"kind", "buffer"}, {"type", "uint"}, {"values", input}}},
                               {"Out", {{"kind", "buffer"}, {"type", "uint"}, {"count", 2}}}}},
                {"dispatch", {{"threads", {2, 1, 1}}}},
                {"expect", {{{"resource", "Out"}, {"values", expected}}}}};
    }
};

TEST_F(IntegerRuns, EveryThirtyTwoBitIntegerGoesInAndComesBackExactly) {
    const auto result = iblkitRun(copyRun({16777216, 4294967294u}, {16777217, 4294967295u}));
    EXPECT_EQ(result.exitCode, 0) << result.out << result.err;
    const auto wrong = iblkitRun(copyRun({16777216, 4294967294u}, {16777216, 4294967295u}));
    EXPECT_EQ(wrong.exitCode, 3) << "16777217 is not 16777216:\n" << wrong.out;
}

TEST_F(IntegerRuns, AValueTheIntegerFormatCannotHoldIsNamed) {
    expectError(copyRun({1, 4294967296.0}, {0, 0}), "resources.In.values[1]: 4294967296 is not an unsigned 32-bit integer");
    expectError(copyRun({1.5, 2}, {0, 0}), "resources.In.values[0]: 1.5 is not an unsigned 32-bit integer");
    expectError(copyRun({1, -1}, {0, 0}), "resources.In.values[1]: -1 is not an unsigned 32-bit integer");
}

TEST_F(RunCli, BindingANameTheShaderLacks) {
    auto run = fastPrefilter();
    run["resources"]["Extra"] = {{"kind", "sampler"}};
    expectError(run, "resources.Extra: the shader has no resource of that name (it has: PrefilterSpecularParameter, "
                     "EnvMap, EnvMapSampler, Prefiltered)");
}

// An array of resources binds one resource per element (the runtime once refused every array);
// the run file must give as many as the shader declares, and no array where it declares one.
TEST_F(RunCli, AnArrayOfResourcesNeedsEveryElement) {
    std::ifstream stream("hlsl/porting/VulkanBindingArray.run.json");
    json run = json::parse(stream);
    run["shader"] = fs::absolute("hlsl/porting/VulkanBindingArray.hlsl").string();
    const auto passed = iblkitRun(run);
    EXPECT_EQ(passed.exitCode, 0) << passed.err << passed.out;
    EXPECT_NE(passed.out.find("4 of 4 expectations passed"), std::string::npos) << passed.out;
    auto fewer = run;
    auto& elements = fewer["resources"]["Mips"]["elements"];
    elements.erase(elements.begin() + 2, elements.end());
    fewer["expect"] = json::array({run["expect"][0]});
    expectError(fewer, "resources.Mips: the shader declares an array of 13, the run file gives 2 elements");
    auto notAnArray = run;
    notAnArray["resources"]["Written"] = {{"kind", "buffer"}, {"elements", json::array({{{"count", 1}}})}};
    expectError(notAnArray, "resources.Written: the shader declares one resource, not an array");
}

TEST_F(RunCli, MissingAResourceTheShaderNeeds) {
    auto run = fastPrefilter();
    run["resources"].erase("EnvMapSampler");
    expectError(run, "the shader needs 'EnvMapSampler' (sampler), which the run file does not give");
}

TEST_F(RunCli, AResourceOfTheWrongKind) {
    auto run = fastPrefilter();
    run["resources"]["EnvMapSampler"] = {{"kind", "buffer"}, {"count", 4}};
    expectError(run, "resources.EnvMapSampler: is a buffer, but the shader declares a sampler");
}

TEST_F(RunCli, AStorageImageOfTheWrongFormat) {
    auto run = example("brdf_lut.run.json");
    run["resources"]["Precomputed"]["format"] = "R32G32_SFLOAT";
    expectError(run, "'Precomputed': wrong format: the shader declares R16G16_SFLOAT, the image is R32G32_SFLOAT");
}

TEST_F(RunCli, ADispatchOfZeroSize) {
    auto run = fastPrefilter();
    run["dispatch"]["threads"] = {32, 0, 6};
    expectError(run, "dispatch of zero size: 32x0x6 threads");
}

TEST_F(RunCli, AnAllocationThatCannotFit) {
    auto run = fastPrefilter();
    run["resources"]["EnvMap"]["size"] = {1 << 20, 1 << 20};
    run["resources"]["EnvMap"]["mips"] = 1;
    expectError(run, "image 'EnvMap': 1048576x1048576 exceeds the device's limit");
}

TEST_F(RunCli, ASaveOfAnUnknownResourceFailsBeforeAnythingIsWritten) {
    auto run = fastPrefilter();
    run["save"] = {{"Prefiltered", (folder / "a.npy").string()}, {"Nope", (folder / "b.npy").string()}};
    expectError(run, "save: no resource named 'Nope'");
    EXPECT_FALSE(fs::exists(folder / "a.npy"));
}

// A save onto the run file, or two saves to one file, is refused before any device work.
TEST_F(RunCli, ASaveOntoAnInputOrOntoAnotherSaveIsRefused) {
    auto run = fastPrefilter();
    run["save"] = {{"Prefiltered", (folder / "test.run.json").string()}};
    expectError(run, "test.run.json: error: this output is also an input of the command");
    run["save"] = {{"Prefiltered", (folder / "a.npy").string()}, {"EnvMap", (folder / "a.npy").string()}};
    expectError(run, "a.npy: error: two outputs of the command are this one file");
    EXPECT_FALSE(fs::exists(folder / "a.npy"));
}

// The driver's refusals named neither the run file nor the resource.
TEST_F(RunCli, ABufferTooLargeForTheDeviceIsNamedByItsKey) {
    std::ofstream(folder / "out.hlsl") << "RWStructuredBuffer<float> Out;\n"
                                          "[numthreads(1, 1, 1)] void main(uint3 id : SV_DispatchThreadId) { Out[id.x] = 1.f; }\n";
    const json run = {{"shader", (folder / "out.hlsl").string()},
                      {"resources", {{"Out", {{"kind", "buffer"}, {"count", 4294967295u}}}}},
                      {"dispatch", {{"threads", {1, 1, 1}}}}};
    expectError(run, "test.run.json: error: resources.Out: buffer 'Out' of 17179869180 bytes cannot be made on this device");
}

TEST_F(RunCli, ADispatchPastTheDevicesLimitNamesTheRunFile) {
    auto run = fastPrefilter();
    run["dispatch"] = {{"groups", {65536, 1, 1}}};
    expectError(run, "test.run.json: error: dispatch: dispatch of 65536 groups on axis 0 exceeds the device's limit of 65535");
}

TEST_F(RunCli, PushConstantsForAShaderThatHasNone) {
    auto run = fastPrefilter();
    run["push_constants"] = {{"Roughness", 0.5}};
    expectError(run, "push_constants: the shader has no push constants");
}

TEST_F(RunCli, ACbufferValueItsMemberCannotHold) {
    auto run = fastPrefilter();
    run["resources"]["PrefilterSpecularParameter"]["members"]["Roughness"] = 1e39;
    expectError(run, "PrefilterSpecularParameter.Roughness is a float: 1e+39 is beyond float's range");
}

TEST_F(RunCli, AMissingDataFile) {
    auto run = fastPrefilter();
    run["resources"]["EnvMap"].erase("fill");
    run["resources"]["EnvMap"]["file"] = "env.bin";
    expectError(run, "env.bin: error: no such data file");
}

// A module whose first OpConstant names a result id past the module's bound: SPIRV-Cross, asked
// to reflect it, dereferenced it and crashed. The validator now refuses it first, in one line.
TEST_F(RunCli, ADamagedSpirvModuleIsRefusedByTheValidatorNotCrashedOn) {
    std::ofstream(folder / "double.hlsl") << "RWStructuredBuffer<float> Out;\n"
                                            "[numthreads(1, 1, 1)] void main(uint3 id : SV_DispatchThreadId) "
                                            "{ Out[id.x] = id.x * 2.f; }\n";
    const auto compiled = runProcess({IBLKIT_EXECUTABLE, "compile", (folder / "double.hlsl").string(), "-o",
                                      (folder / "double.spv").string()});
    ASSERT_EQ(compiled.exitCode, 0) << compiled.err;
    std::ifstream in(folder / "double.spv", std::ios::binary);
    std::vector<uint32_t> words(fs::file_size(folder / "double.spv") / 4);
    in.read(reinterpret_cast<char*>(words.data()), std::streamsize(words.size() * 4));
    constexpr uint32_t kOpConstant = 43;
    size_t at = 5;
    while (at < words.size() && (words[at] & 0xFFFF) != kOpConstant) at += words[at] >> 16;
    ASSERT_LT(at + 2, words.size()) << "no OpConstant in the module";
    words[at + 2] |= 0x0E000000u; // its result id, far past the bound
    std::ofstream(folder / "damaged.spv", std::ios::binary)
        .write(reinterpret_cast<const char*>(words.data()), std::streamsize(words.size() * 4));

    const json run = {{"shader", (folder / "damaged.spv").string()},
                      {"resources", {{"Out", {{"kind", "buffer"}, {"count", 4}}}}},
                      {"dispatch", {{"threads", {4, 1, 1}}}}};
    const auto result = iblkitRun(run);
    EXPECT_EQ(result.exitCode, 1) << "a signal or an abort ends a process otherwise: " << result.err;
    EXPECT_NE(result.err.find("damaged.spv: error: the SPIR-V is not valid for Vulkan 1.1"), std::string::npos) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
}

// 65535 x 1024 groups of 64 invocations, each 65535 sines: days on lavapipe. The wait for it
// was unbounded; now the run ends at its --timeout with one line (the killer stops a regression).
TEST_F(RunCli, AShaderThatDoesNotEndInTimeEndsTheRunWithOneLine) {
    std::ofstream(folder / "forever.hlsl") << "RWStructuredBuffer<float> Out;\n"
                                             "[numthreads(64, 1, 1)] void main(uint3 id : SV_DispatchThreadId) {\n"
                                             "    float x = Out[id.x & 3];\n"
                                             "    for (uint i = 0; i < 65535; ++i) x = sin(x) * 0.5f + Out[i & 3];\n"
                                             "    Out[id.x & 3] = x;\n}\n";
    const json run = {{"shader", (folder / "forever.hlsl").string()},
                      {"resources", {{"Out", {{"kind", "buffer"}, {"count", 4}}}}},
                      {"dispatch", {{"groups", {65535, 1024, 1}}}}};
    const auto path = folder / "forever.run.json";
    std::ofstream(path) << run.dump(2);
    const auto started = std::chrono::steady_clock::now();
    const auto result = runProcess({IBLKIT_EXECUTABLE, "run", path.string(), "--timeout", "1"}, {}, 120);
    const auto seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    EXPECT_EQ(result.exitCode, 1) << result.err;
    EXPECT_LT(seconds, 60) << "the wait was not bounded";
    EXPECT_NE(result.err.find("forever.run.json: error: the device did not finish a submission within 1 s"),
              std::string::npos) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
}

} // namespace
} // namespace iblkit::testing
