// The bake's cache: a repeated bake opens no device and writes the same files, a changed setting
// recomputes only what depends on it, one LUT serves every environment, a damaged entry is
// computed again, keys follow every kernel source and header, and bakes racing on one cache
// both end well.
#include "bake.hpp"
#include "bake_cache.hpp"
#include "float_image.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <thread>

namespace iblkit::bake {
namespace {

namespace fs = std::filesystem;

std::string fileText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

class BakeCache : public ::testing::Test {
protected:
    BakeSettings settings(const std::string& output) const {
        BakeSettings s;
        s.outputDir = scratch.path() / output;
        s.size = 32;
        s.lutSize = 16;
        s.irradianceSize = 8;
        s.cache = scratch.path() / "cache";
        return s;
    }
    static BakeSummary bake(const BakeSettings& s) {
        BakeProgress progress(true);
        return bakeEnvironment(s, "test", progress);
    }
    static bool openedADevice(const BakeSummary& summary) {
        return std::any_of(summary.steps.begin(), summary.steps.end(), [](const auto& step) { return step.name == "device"; });
    }
    iblkit::testing::TempFolder scratch;
};

TEST_F(BakeCache, ARepeatedBakeOpensNoDeviceAndWritesTheSameFiles) {
    const auto first = bake(settings("first"));
    EXPECT_EQ(first.cache.hits, 0u);
    EXPECT_TRUE(openedADevice(first));
    const auto second = bake(settings("second"));
    EXPECT_EQ(second.cache.misses, 0u);
    EXPECT_EQ(second.cache.hits, 4u) << "specular, LUT, irradiance, preview";
    EXPECT_FALSE(openedADevice(second));
    for (const char* file : {"specular.ktx2", "brdf_lut.ktx2", "irradiance.ktx2", "preview.png"})
        EXPECT_EQ(fileText(scratch.path() / "first" / file), fileText(scratch.path() / "second" / file)) << file;
}

TEST_F(BakeCache, AChangedSettingRecomputesOnlyWhatDependsOnIt) {
    bake(settings("first"));
    auto biggerLut = settings("second");
    biggerLut.lutSize = 32;
    const auto second = bake(biggerLut);
    EXPECT_EQ(second.cache.hits, 2u) << "specular and irradiance";
    EXPECT_EQ(second.cache.misses, 2u) << "the LUT, and the preview that shows it";
    EXPECT_EQ(fileText(scratch.path() / "first" / "specular.ktx2"), fileText(scratch.path() / "second" / "specular.ktx2"));
}

TEST_F(BakeCache, OneLutServesEveryEnvironment) {
    bake(settings("sky"));
    image_io::writeExr(scratch.path() / "grey.exr", {64, 32, 3, std::vector<float>(64 * 32 * 3, 0.5f)});
    auto grey = settings("grey");
    grey.environment = scratch.path() / "grey.exr";
    const auto summary = bake(grey);
    EXPECT_EQ(summary.cache.hits, 1u) << "the LUT alone";
    EXPECT_EQ(fileText(scratch.path() / "sky" / "brdf_lut.ktx2"), fileText(scratch.path() / "grey" / "brdf_lut.ktx2"));
}

TEST_F(BakeCache, ADamagedEntryIsComputedAgain) {
    bake(settings("first"));
    fs::path largest; // the specular chain's entry
    for (const auto& entry : fs::recursive_directory_iterator(scratch.path() / "cache"))
        if (entry.is_regular_file() && (largest.empty() || entry.file_size() > fs::file_size(largest))) largest = entry.path();
    {
        std::fstream file(largest, std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(-5, std::ios::end);
        file.put('!');
    }
    const auto second = bake(settings("second"));
    EXPECT_EQ(second.cache.corrupt, 1u);
    EXPECT_TRUE(openedADevice(second));
    EXPECT_EQ(fileText(scratch.path() / "first" / "specular.ktx2"), fileText(scratch.path() / "second" / "specular.ktx2"));
    EXPECT_EQ(bake(settings("third")).cache.misses, 0u) << "written anew";
}

TEST_F(BakeCache, BakesRacingOnOneCacheBothEndWell) {
    std::vector<std::thread> bakes;
    std::vector<std::string> errors(2);
    for (int i = 0; i < 2; ++i)
        bakes.emplace_back([&, i] {
            try {
                bake(settings("race" + std::to_string(i)));
            } catch (const std::exception& error) {
                errors[i] = error.what();
            }
        });
    for (auto& thread : bakes) thread.join();
    EXPECT_EQ(errors, (std::vector<std::string>{"", ""}));
    for (const char* file : {"specular.ktx2", "brdf_lut.ktx2", "irradiance.ktx2", "preview.png"})
        EXPECT_EQ(fileText(scratch.path() / "race0" / file), fileText(scratch.path() / "race1" / file)) << file;
    EXPECT_EQ(bake(settings("after")).cache.misses, 0u);
}

TEST(BakeKeys, FollowEveryKernelSourceAndHeader) {
    BakeSettings settings;
    EnvironmentInput input;
    const auto plan = planBake(settings, 256, std::nullopt);
    const vulkan::DeviceInfo device{0, "llvmpipe", "cpu", "mesa", "1.3", true};
    const auto base = bakeKeys(settings, input, 256, plan, device, "1");
    auto files = kernels::embeddedShaderFiles();
    files.at("hlsl/document/Common/PBR.fxh") += "\n// a changed include\n";
    const auto changedHeader = bakeKeys(settings, input, 256, plan, device, "1", files);
    EXPECT_NE(base.specular, changedHeader.specular);
    EXPECT_NE(base.lut, changedHeader.lut);
    files = kernels::embeddedShaderFiles();
    files.at("hlsl/IrradianceCubeCS.hlsl") += "\n";
    const auto changedIrradiance = bakeKeys(settings, input, 256, plan, device, "1", files);
    EXPECT_EQ(base.specular, changedIrradiance.specular) << "a kernel the output does not run";
    EXPECT_NE(base.irradiance, changedIrradiance.irradiance);
    EXPECT_NE(base.specular, bakeKeys(settings, input, 256, plan, {0, "a GPU", "discrete-gpu", "x", "1.3", false}, "1").specular);
    EXPECT_NE(base.specular, bakeKeys(settings, input, 256, plan, device, "2").specular) << "the tool's version";
    EXPECT_NE(base.specular, bakeKeys(settings, input, 128, planBake(settings, 128, std::nullopt), device, "1").specular);
}

} // namespace
} // namespace iblkit::bake
