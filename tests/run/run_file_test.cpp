#include "atomic_output.hpp"
#include "data_file.hpp"
#include "run_error.hpp"
#include "run_executor.hpp"
#include "run_file.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace iblkit::run {
namespace {

namespace fs = std::filesystem;

class RunFiles : public ::testing::Test {
protected:

    fs::path write(const std::string& text) const {
        const auto path = folder / "test.run.json";
        std::ofstream(path) << text;
        return path;
    }
    std::string errorOf(const std::string& text) const {
        try {
            readRunFile(write(text));
        } catch (const RunError& error) {
            return error.what();
        }
        return "no error";
    }
    testing::TempFolder scratch;
    const fs::path& folder = scratch.path();
};

TEST_F(RunFiles, TheDocumentedPrefilterExampleReadsAsWritten) {
    const auto spec = readRunFile("docs/examples/prefilter_white_furnace.run.json");
    EXPECT_EQ(spec.shader, fs::path("docs/examples/../../hlsl/document/PrefilterSpecularCS.hlsl"));
    EXPECT_EQ(spec.defines.at("SAMPLE_COUNT"), "1024");
    ASSERT_EQ(spec.resources.size(), 4u);
    const auto& env = *std::find_if(spec.resources.begin(), spec.resources.end(), [](auto& r) { return r.name == "EnvMap"; });
    EXPECT_EQ(env.dimension, "cube");
    EXPECT_EQ(env.layers, 6u);
    EXPECT_EQ(env.mips, 7u);
    EXPECT_EQ(env.initial.fill, (std::vector<double>{1, 1, 1, 1}));
    EXPECT_EQ(spec.threads, (std::array<uint32_t, 3>{32, 32, 6}));
    ASSERT_EQ(spec.expectations.size(), 1u);
    EXPECT_EQ(spec.expectations[0].tolerance.absolute, 1e-4);
    EXPECT_EQ(spec.saves.at("Prefiltered"), fs::path("docs/examples/prefiltered.npy"));
}

TEST_F(RunFiles, CompileOptionsAreReadAsTypedValues) {
    const auto spec = readRunFile(write(R"({"shader": "x.hlsl", "dispatch": {"threads": [1]}, "enable_16bit_types": true,
                                           "hlsl_version": "2018"})"));
    const auto options = compileOptionsOf(spec);
    EXPECT_TRUE(options.enable16BitTypes);
    EXPECT_EQ(options.hlslVersion, lowering::HlslVersion::Hlsl2018);
    EXPECT_EQ(options.source, folder / "x.hlsl");
}

// An array of resources: one spec per element, named as expectations name them, each bound to
// its element of the shader's array.
TEST_F(RunFiles, AnArrayOfResourcesIsOneSpecPerElement) {
    const auto spec = readRunFile(write(R"({"shader": "x.hlsl", "dispatch": {"threads": [1]}, "resources": {
        "Levels": {"kind": "buffer", "elements": [{"type": "uint", "count": 2}, {"values": [1, 2, 3]}]}}})"));
    ASSERT_EQ(spec.resources.size(), 2u);
    EXPECT_EQ(spec.resources[0].name, "Levels[0]");
    EXPECT_EQ(spec.resources[1].name, "Levels[1]");
    for (uint32_t i = 0; i < 2; ++i) {
        EXPECT_EQ(spec.resources[i].binding, "Levels");
        EXPECT_EQ(spec.resources[i].element, i);
        EXPECT_EQ(spec.resources[i].kind, "buffer");
    }
    EXPECT_EQ(spec.resources[0].elementType, "uint");
    EXPECT_EQ(spec.resources[1].initial.values.size(), 3u);
    const std::string head = R"({"shader": "x.hlsl", "dispatch": {"threads": [1]}, "resources": {"L": )";
    EXPECT_NE(errorOf(head + R"({"kind": "buffer", "elements": []}}})").find("resources.L.elements: is empty"), std::string::npos);
    EXPECT_NE(errorOf(head + R"({"elements": [{}]}}})").find("resources.L: needs a \"kind\""), std::string::npos);
    EXPECT_NE(errorOf(head + R"({"kind": "buffer", "elements": [{"kind": "image"}]}}})")
                  .find("resources.L.elements[0]: takes its kind from the array"),
              std::string::npos);
    EXPECT_NE(errorOf(head + R"({"kind": "buffer", "elements": [{"count": 1}], "count": 2}}})").find("unknown key 'count'"),
              std::string::npos);
}

TEST_F(RunFiles, MistakesAreNamedWithTheirKey) {
    const std::string head = R"({"shader": "x.hlsl", )";
    EXPECT_NE(errorOf("{").find("not valid JSON"), std::string::npos);
    EXPECT_NE(errorOf(R"({"dispatch": {"threads": [1]}})").find("needs a \"shader\""), std::string::npos);
    EXPECT_NE(errorOf(head + R"("resources": {}})").find("needs a \"dispatch\""), std::string::npos);
    EXPECT_NE(errorOf(head + R"("dispatch": {"threads": [1], "groups": [1]}})").find("exactly one of"), std::string::npos);
    EXPECT_NE(errorOf(head + R"("dispatch": {"threads": [1]}, "dispath": 1})").find("unknown key 'dispath'"), std::string::npos);
    EXPECT_NE(errorOf(head + R"("dispatch": {"threads": [1]}, "resources": {"A": {"kind": "texture"}}})")
                  .find("resources.A.kind: unknown value 'texture' (buffer, cbuffer, image, cube, storage_image, sampler)"),
              std::string::npos);
    EXPECT_NE(errorOf(head + R"("dispatch": {"threads": [1]}, "resources": {"A": {"kind": "image", "format": "R32_SFLOAT"}}})")
                  .find("resources.A: needs a \"size\""),
              std::string::npos);
    EXPECT_NE(errorOf(head + R"("dispatch": {"threads": [1]}, "expect": [{"resource": "A"}]})")
                  .find("expect[0]: needs exactly one of"),
              std::string::npos);
    EXPECT_NE(errorOf(head + R"("dispatch": {"threads": [1]}, "expect": [{"resource": "A", "range": [1, 0]}]})")
                  .find("expect[0].range: takes [min, max]"),
              std::string::npos);
}

// Values that were cut, wrapped or taken silently, or that ended in a raw
// "[json.exception.type_error.302]": each is refused, naming its key, before any device work.
TEST_F(RunFiles, ValuesOutOfTypeOrRangeAreRefusedWithTheirKey) {
    const auto run = [](const std::string& resource, const std::string& rest = "") {
        return R"({"shader": "x.hlsl", "dispatch": {"threads": [1]}, "resources": {"A": )" + resource + "}" + rest + "}";
    };
    const std::pair<std::string, std::string> cases[] = {
        {R"({"shader": "x.hlsl", "dispatch": {"threads": [4294967296, 1, 1]}})",
         "dispatch.threads[0]: 4294967296 is outside [0, 4294967295]"},
        {R"({"shader": "x.hlsl", "dispatch": {"groups": [1, 8589934593]}})", "dispatch.groups[1]: 8589934593 is outside"},
        {run(R"({"kind": "buffer", "count": 4294967296})"), "resources.A.count: 4294967296 is outside [1, 4294967295]"},
        {run(R"({"kind": "buffer", "count": 8.5})"), "resources.A.count: 8.5 is not a whole number"},
        {run(R"({"kind": "buffer", "count": -1})"), "resources.A.count: -1 is outside"},
        {run(R"({"kind": "buffer", "count": "4"})"), "resources.A.count: must be a whole number"},
        {run(R"({"kind": "buffer", "type": "banana", "count": 4})"), "resources.A.type: unknown value 'banana' (float, uint, int)"},
        {run(R"({"kind": "buffer", "count": 4, "size_bytes": 16})"), "resources.A: takes \"count\" or \"size_bytes\", not both"},
        {run(R"({"kind": "buffer", "count": 4, "fill": []})"), "resources.A.fill: must not be empty"},
        {run(R"({"kind": "buffer", "count": 4, "fill": 1, "values": [1, 2, 3, 4]})"), "resources.A: takes one of"},
        {run(R"({"kind": "image", "format": "R32_SFLOAT", "size": [4, 4, 4]})"), "resources.A.size: takes 1 to 2 numbers"},
        {run(R"({"kind": "image", "format": "R32_SFLOAT", "size": [4294967296, 4]})"), "resources.A.size[0]: 4294967296 is outside"},
        {run(R"({"kind": "image", "format": "R32_SFLOAT", "size": [4, 4], "mips": 0})"), "resources.A.mips: 0 is outside [1, 32]"},
        {run(R"({"kind": "image", "format": 7, "size": [4, 4]})"), "resources.A.format: must be a string"},
        {run(R"({"kind": "sampler", "filter": "cubic"})"), "resources.A.filter: unknown value 'cubic' (nearest, linear)"},
        {run(R"({"kind": "cbuffer", "members": {"R": "half"}})"), "resources.A.members.R: must be a number or an array of numbers"},
        {run(R"({"kind": "buffer", "count": 4})", R"(, "expect": [{"resource": "A", "fill": 0, "tolerance": {"abs": -1}}])"),
         "expect[0].tolerance.abs: must not be negative (it is -1)"},
        {R"({"shader": "x.hlsl", "include": "hlsl", "dispatch": {"threads": [1]}})", "include: must be an array"},
        {R"({"shader": 5, "dispatch": {"threads": [1]}})", "shader: must be a string"},
        {R"({"shader": "x.hlsl", "dispatch": {"threads": [1]}, "defines": {"N": [1]}})", "defines.N: must be a string"},
        {R"({"shader": "x.hlsl", "dispatch": {"threads": [1]}, "enable_16bit_types": 1})",
         "enable_16bit_types: must be true or false"},
        {R"({"shader": "x.hlsl", "dispatch": {"threads": [1]}, "hlsl_version": "2020"})",
         "hlsl_version: unknown value '2020' (2018, 2021)"},
    };
    for (const auto& [text, expected] : cases) {
        const auto message = errorOf(text);
        EXPECT_NE(message.find("test.run.json: error: " + expected), std::string::npos) << text << "\n" << message;
        EXPECT_EQ(message.find("json.exception"), std::string::npos) << message;
    }
}

TEST_F(RunFiles, IntegerNpyFilesHoldEveryThirtyTwoBitValueExactly) {
    for (const char* name : {"R32_UINT", "R32_SINT"}) {
        const auto& format = vulkan::texelFormatNamed(name);
        const std::vector<double> values = format.kind == vulkan::ComponentKind::UInt
                                               ? std::vector<double>{16777217, 4294967294.0, 0}
                                               : std::vector<double>{-16777217, 2147483647, -2147483648.0};
        files::writeFileAtomically(folder / "a.npy", encodeValues(folder / "a.npy", format, values, {3}));
        EXPECT_EQ(readValues(folder / "a.npy", format, 3), values) << name;
    }
}

TEST_F(RunFiles, NpyFilesRoundTripAndRawFilesMustHaveTheRightSize) {
    const auto& format = vulkan::texelFormatNamed("R16G16_SFLOAT");
    const std::vector<double> values = {0.5f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f};
    files::writeFileAtomically(folder / "a.npy", encodeValues(folder / "a.npy", format, values, {1, 1, 3, 2}));
    EXPECT_EQ(readValues(folder / "a.npy", format, 6), values);
    std::ifstream npy(folder / "a.npy", std::ios::binary);
    std::string header(128, '\0');
    npy.read(header.data(), 128);
    EXPECT_NE(header.find("'shape': (1, 1, 3, 2)"), std::string::npos);
    EXPECT_EQ(fs::file_size(folder / "a.npy") % 16, (6 * 4) % 16) << "the header is padded to 64 bytes";
    files::writeFileAtomically(folder / "a.bin", encodeValues(folder / "a.bin", format, values, {6}));
    EXPECT_EQ(fs::file_size(folder / "a.bin"), 12u) << "raw data in the format: 6 halves";
    EXPECT_EQ(readValues(folder / "a.bin", format, 6), values);
    EXPECT_THROW(readValues(folder / "a.bin", format, 7), RunError);
    EXPECT_EQ(readValues(folder / "a.npy", format).size(), 6u) << "without a count, as many values as the file holds";
    EXPECT_THROW(readValues(folder / "missing.bin", format, 6), RunError);
}

} // namespace
} // namespace iblkit::run
