// A code base's manifest and a list of entries become the compile options its build would pass;
// what cannot be read is one error naming the file, the key or the line.
#include "codebase_manifest.hpp"
#include "porting_error.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

namespace iblkit::porting {
namespace {

const char* kManifest = R"({
  "name": "Engine", "repository": "https://example.org/engine", "commit": "0123456789abcdef",
  "requires": [{"name": "Core", "repository": "https://example.org/core", "commit": "fedcba"}],
  "include_dirs": ["Shaders/Common"], "defines": {"GLOBAL": "2", "BARE": ""},
  "flags": ["-Zpr", "-O3"],
  "generated_files": {"Generated.h": "#define FROM_BUILD 1\n"},
  "force_includes": ["@Core/Prelude.fxh"],
  "configurations": [
    {"file": "Shaders/Tonemap.hlsl", "entry": "PSMain", "profile": "ps_6_0", "defines": {"GLOBAL": "3"},
     "flags": ["-enable-16bit-types", "-fvk-t-shift 10 0"], "target": "vulkan"},
    {"file": "Shaders/Old.hlsl", "entry": "VS", "profile": "vs_5_0", "name": "old"},
    {"file": "@Core/Trace.hlsl", "entry": "RayGen", "profile": "lib_6_3"}
  ]})";

TEST(CodeBaseManifest, ConfigurationsCarryTheBuildsSettings) {
    iblkit::testing::TempFolder folder;
    const auto manifest = folder.write("engine.json", kManifest);
    const auto root = folder.path() / "Engine";
    const auto base = readCodeBaseManifest(manifest, root);
    ASSERT_EQ(base.configurations.size(), 3u);
    const auto& tonemap = base.configurations[0];
    EXPECT_EQ(tonemap.label, "Tonemap.hlsl:PSMain:ps_6_0");
    EXPECT_EQ(tonemap.options.source, root / "Shaders/Tonemap.hlsl");
    EXPECT_EQ(tonemap.options.stage, compiler::ShaderStage::Fragment);
    EXPECT_EQ(tonemap.options.defines.at("GLOBAL"), "3");
    EXPECT_EQ(tonemap.options.defines.at("BARE"), "1"); // -D NAME is NAME=1 in DXC and fxc
    EXPECT_TRUE(tonemap.options.enable16BitTypes);
    EXPECT_TRUE(tonemap.options.rowMajorByDefault);
    EXPECT_EQ(tonemap.options.bindingShifts.of(compiler::RegisterClass::ShaderResource), 10u);
    EXPECT_EQ(tonemap.options.hlslVersion, lowering::HlslVersion::Hlsl2021);
    EXPECT_EQ(tonemap.options.virtualFiles.at("Generated.h"), "#define FROM_BUILD 1\n");
    ASSERT_EQ(tonemap.options.forceIncludes.size(), 1u);
    EXPECT_EQ(tonemap.options.forceIncludes[0].filename(), "Prelude.fxh");
    EXPECT_EQ(tonemap.ignoredFlags, std::vector<std::string>{"-O3"});
    EXPECT_EQ(tonemap.target, BuildTarget::Vulkan);
    // fxc's Shader Model 5 takes HLSL 2018.
    EXPECT_EQ(base.configurations[1].label, "old");
    EXPECT_EQ(base.configurations[1].options.hlslVersion, lowering::HlslVersion::Hlsl2018);
    EXPECT_EQ(base.configurations[2].options.source, folder.path() / "Core" / "Trace.hlsl");
    EXPECT_TRUE(base.configurations[2].refusedStage());
    EXPECT_FALSE(tonemap.refusedStage());
}

std::string codeBaseErrorOf(const std::string& manifest) {
    iblkit::testing::TempFolder folder;
    try {
        readCodeBaseManifest(folder.write("m.json", manifest), folder.path());
    } catch (const PortingError& error) {
        return error.what();
    }
    return "";
}

std::string withCodeBaseConfiguration(const std::string& configuration) {
    return R"({"name": "E", "repository": "r", "commit": "c", "configurations": [)" + configuration + "]}";
}

TEST(CodeBaseManifest, BadManifestsAreRefusedNamingTheKey) {
    EXPECT_NE(codeBaseErrorOf("{").find("not valid JSON"), std::string::npos);
    EXPECT_NE(codeBaseErrorOf(R"({"repository": "r", "commit": "c", "configurations": []})").find("needs \"name\""), std::string::npos);
    EXPECT_NE(codeBaseErrorOf(withCodeBaseConfiguration(R"({"file": "a.hlsl", "entry": "main", "profile": "ps_9"})"))
                  .find("configurations[0].profile"),
              std::string::npos);
    EXPECT_NE(codeBaseErrorOf(withCodeBaseConfiguration(R"({"file": "a.hlsl", "entry": "main", "profile": "ps_6_0", "flags": ["-frobnicate"]})"))
                  .find("'-frobnicate' is not a DXC or fxc flag the kit knows"),
              std::string::npos);
    EXPECT_NE(codeBaseErrorOf(withCodeBaseConfiguration(R"({"file": "@Other/a.hlsl", "entry": "main", "profile": "ps_6_0"})"))
                  .find("which \"requires\" does not list"),
              std::string::npos);
    EXPECT_NE(codeBaseErrorOf(withCodeBaseConfiguration(R"({"file": "a.hlsl", "entry": "main", "profile": "ps_6_0"},
                                           {"file": "b/a.hlsl", "entry": "main", "profile": "ps_6_0"})"))
                  .find("is another configuration's too"),
              std::string::npos);
    EXPECT_NE(codeBaseErrorOf(withCodeBaseConfiguration(R"({"file": "a.hlsl", "entry": "main", "profile": "ps_6_0", "flags": ["-HV 2019"]})"))
                  .find("-HV takes"),
              std::string::npos);
}

TEST(EntryList, LinesAreFileEntryProfileAndDxcArguments) {
    iblkit::testing::TempFolder folder;
    const auto list = folder.write("entries.txt", "# a comment\n"
                                                  "Post/Blur.hlsl CSMain cs_6_2 -DRADIUS=4 -D WIDE -I Common -enable-16bit-types\n"
                                                  "\n"
                                                  "Mesh.hlsl VS vs_6_0 -spirv -fvk-b-shift 4 0\n");
    const auto base = readEntryList(list, folder.path());
    ASSERT_EQ(base.configurations.size(), 2u);
    const auto& blur = base.configurations[0].options;
    EXPECT_EQ(blur.defines.at("RADIUS"), "4");
    EXPECT_EQ(blur.defines.at("WIDE"), "1");
    EXPECT_EQ(blur.includeDirs, std::vector<std::filesystem::path>{folder.path() / "Common"});
    EXPECT_TRUE(blur.enable16BitTypes);
    EXPECT_EQ(base.configurations[1].target, BuildTarget::Vulkan);
    EXPECT_EQ(base.configurations[1].options.bindingShifts.of(compiler::RegisterClass::ConstantBuffer), 4u);
}

TEST(EntryList, ABadLineIsNamedByItsNumber) {
    iblkit::testing::TempFolder folder;
    const auto list = folder.write("entries.txt", "A.hlsl main ps_6_0\nB.hlsl main\n");
    try {
        readEntryList(list, folder.path());
        FAIL() << "not refused";
    } catch (const PortingError& error) {
        EXPECT_NE(std::string(error.what()).find("entries.txt:2: error"), std::string::npos) << error.what();
    }
}

} // namespace
} // namespace iblkit::porting
