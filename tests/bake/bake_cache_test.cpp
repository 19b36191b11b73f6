// The bake's cache: a repeated bake opens no device and writes the same files, a changed setting
// recomputes only what depends on it, one LUT serves every environment, a damaged entry is
// computed again, and so is one moved to another key's place, keys follow every kernel source and header, and bakes racing on one cache
// both end well.
#include "bake.hpp"
#include "resolved_at.hpp"
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
    EXPECT_EQ(second.cache.hits, 6u) << "specular, LUT, irradiance, the sky's lights, the lobe table, preview";
    EXPECT_FALSE(openedADevice(second));
    for (const char* file : {"specular.ktx2", "brdf_lut.ktx2", "irradiance.ktx2", "preview.png"})
        EXPECT_EQ(fileText(scratch.path() / "first" / file), fileText(scratch.path() / "second" / file)) << file;
}

TEST_F(BakeCache, AChangedSettingRecomputesOnlyWhatDependsOnIt) {
    bake(settings("first"));
    auto biggerLut = settings("second");
    biggerLut.lutSize = 32;
    const auto second = bake(biggerLut);
    EXPECT_EQ(second.cache.hits, 4u) << "specular, irradiance, the lights and the lobe table";
    EXPECT_EQ(second.cache.misses, 2u) << "the LUT, and the preview that shows it";
    EXPECT_EQ(fileText(scratch.path() / "first" / "specular.ktx2"), fileText(scratch.path() / "second" / "specular.ktx2"));
}

TEST_F(BakeCache, OneLutServesEveryEnvironment) {
    bake(settings("sky"));
    image_io::writeExr(scratch.path() / "grey.exr", {64, 32, 3, std::vector<float>(64 * 32 * 3, 0.5f)});
    auto grey = settings("grey");
    grey.environment = scratch.path() / "grey.exr";
    const auto summary = bake(grey);
    EXPECT_EQ(summary.cache.hits, 2u) << "the LUT and the lobe table, which depend on no environment";
    EXPECT_EQ(fileText(scratch.path() / "sky" / "brdf_lut.ktx2"), fileText(scratch.path() / "grey" / "brdf_lut.ktx2"));
}

// Kernels and the pipeline cache outlive a bake: a second environment compiles nothing, and its
// files are those of a bake that compiled everything.
TEST_F(BakeCache, ASecondEnvironmentCompilesNoKernel) {
    image_io::writeExr(scratch.path() / "grey.exr", {64, 32, 3, std::vector<float>(64 * 32 * 3, 0.5f)});
    image_io::writeExr(scratch.path() / "dim.exr", {64, 32, 3, std::vector<float>(64 * 32 * 3, 0.125f)});
    auto grey = settings("grey");
    grey.environment = scratch.path() / "grey.exr";
    const auto first = bake(grey);
    EXPECT_GT(first.compiledKernels.misses, 0u);
    auto dim = settings("dim");
    dim.environment = scratch.path() / "dim.exr";
    const auto second = bake(dim);
    EXPECT_EQ(second.compiledKernels.misses, 0u);
    // The first bake asks twice for DownsampleCubeCS (the source's chain, the residual's): one hit.
    EXPECT_EQ(second.compiledKernels.hits, first.compiledKernels.misses + first.compiledKernels.hits - 2)
        << "all but the LUT's grid and resample kernels: the LUT is cached";
    EXPECT_GE(second.pipelineCacheBytes, 32u) << "the first bake's pipeline cache, header and all";
    auto uncached = settings("uncached");
    uncached.environment = dim.environment;
    uncached.cache.reset();
    EXPECT_EQ(bake(uncached).compiledKernels.misses, 0u) << "no cache, nothing counted";
    for (const char* file : {"specular.ktx2", "irradiance.ktx2", "preview.png"})
        EXPECT_EQ(fileText(scratch.path() / "dim" / file), fileText(scratch.path() / "uncached" / file)) << file;
}

TEST_F(BakeCache, ADamagedEntryIsComputedAgain) {
    bake(settings("first"));
    fs::path specular; // the entry whose payload is the specular chain
    for (const auto& entry : fs::recursive_directory_iterator(scratch.path() / "cache"))
        if (entry.is_regular_file() && fileText(entry.path()).find(R"("name":"specular")") != std::string::npos) specular = entry.path();
    ASSERT_FALSE(specular.empty());
    {
        std::fstream file(specular, std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(-5, std::ios::end);
        file.put('!');
    }
    const auto second = bake(settings("second"));
    EXPECT_EQ(second.cache.corrupt, 1u);
    EXPECT_EQ(second.cache.hits, 5u) << "the LUT, irradiance, lights, lobe table and preview entries are whole";
    EXPECT_TRUE(openedADevice(second));
    EXPECT_EQ(fileText(scratch.path() / "first" / "specular.ktx2"), fileText(scratch.path() / "second" / "specular.ktx2"));
    EXPECT_EQ(bake(settings("third")).cache.misses, 0u) << "written anew";
}

// The specular entry of another environment copied to this one's place: damaged, not served.
TEST_F(BakeCache, AnEntryMovedToAnotherKeysPlaceIsDamagedNotServed) {
    const auto specularEntries = [&] {
        std::vector<fs::path> found;
        for (const auto& entry : fs::recursive_directory_iterator(scratch.path() / "cache"))
            if (entry.is_regular_file() && fileText(entry.path()).find(R"("name":"specular")") != std::string::npos)
                found.push_back(entry.path());
        return found;
    };
    bake(settings("sky"));
    const auto skySpecular = specularEntries();
    ASSERT_EQ(skySpecular.size(), 1u);
    image_io::writeExr(scratch.path() / "grey.exr", {64, 32, 3, std::vector<float>(64 * 32 * 3, 0.5f)});
    auto grey = settings("grey");
    grey.environment = scratch.path() / "grey.exr";
    bake(grey);
    auto greySpecular = specularEntries();
    std::erase(greySpecular, skySpecular[0]);
    ASSERT_EQ(greySpecular.size(), 1u);
    fs::copy_file(skySpecular[0], greySpecular[0], fs::copy_options::overwrite_existing);
    grey.outputDir = scratch.path() / "grey-again";
    const auto again = bake(grey);
    EXPECT_EQ(again.cache.corrupt, 1u);
    EXPECT_EQ(fileText(scratch.path() / "grey" / "specular.ktx2"), fileText(scratch.path() / "grey-again" / "specular.ktx2"));
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

TEST_F(BakeCache, AValidatedBakeNeitherReadsNorWritesTheCache) {
    bake(settings("first"));
    auto validated = settings("validated");
    validated.context.validation = true;
    const auto summary = bake(validated);
    EXPECT_EQ(summary.cache.hits + summary.cache.misses, 0u);
    EXPECT_TRUE(openedADevice(summary)) << "the layer watched every step";
}

TEST_F(BakeCache, ACacheThatCannotBeWrittenIsAWarningNotAFailure) {
    std::ofstream(scratch.path() / "not-a-folder") << "a file";
    auto s = settings("out");
    s.cache = scratch.path() / "not-a-folder";
    const auto summary = bake(s);
    EXPECT_TRUE(fs::exists(scratch.path() / "out" / "specular.ktx2"));
    ASSERT_EQ(summary.cacheWarnings.size(), 1u);
    EXPECT_NE(summary.cacheWarnings[0].find("cannot make the cache folder"), std::string::npos) << summary.cacheWarnings[0];
}

TEST(BakeKeys, FollowEveryKernelSourceAndHeader) {
    BakeSettings settings;
    EnvironmentInput input;
    const auto plan = planBake(resolvedAt(settings, 256), std::nullopt);
    const vulkan::DeviceInfo device{0, "llvmpipe", "cpu", "mesa", "1.3", true};
    const auto base = bakeKeys(resolvedAt(settings, 256), input, plan, device, "1");
    const auto keysWithChanged = [&](const std::string& path) {
        auto files = kernels::embeddedShaderFiles();
        files.at(path) += "\n// changed\n";
        return bakeKeys(resolvedAt(settings, 256), input, plan, device, "1", files);
    };
    const auto header = keysWithChanged("hlsl/document/Common/PBR.fxh"); // an include: every output's key
    EXPECT_TRUE(header.specular != base.specular && header.lut != base.lut && header.irradiance != base.irradiance);
    const auto prefilter = keysWithChanged("hlsl/PrefilterConvolutionCS.hlsl"); // the default prefilter
    EXPECT_NE(prefilter.specular, base.specular);
    EXPECT_NE(prefilter.preview, base.preview) << "the preview shows the specular chain";
    EXPECT_EQ(prefilter.lut, base.lut);
    EXPECT_EQ(prefilter.irradiance, base.irradiance);
    const auto lutGrid = keysWithChanged("hlsl/BrdfLutGridCS.hlsl"); // the default LUT's
    EXPECT_NE(lutGrid.lut, base.lut);
    EXPECT_EQ(lutGrid.specular, base.specular);
    const auto sky = keysWithChanged("hlsl/SkyCubeCS.hlsl"); // the built-in environment's source
    EXPECT_TRUE(sky.specular != base.specular && sky.irradiance != base.irradiance);
    EXPECT_EQ(sky.lut, base.lut) << "no environment in the LUT's key";
    const auto irradiance = keysWithChanged("hlsl/IrradianceCubeCS.hlsl");
    EXPECT_EQ(irradiance.specular, base.specular) << "a kernel the output does not run";
    EXPECT_NE(irradiance.irradiance, base.irradiance);
    EXPECT_NE(base.specular, bakeKeys(resolvedAt(settings, 256), input, plan, {0, "a GPU", "discrete-gpu", "x", "1.3", false}, "1").specular);
    EXPECT_NE(base.specular, bakeKeys(resolvedAt(settings, 256), input, plan, device, "2").specular) << "the tool's version";
    EXPECT_NE(base.specular, bakeKeys(resolvedAt(settings, 128), input, planBake(resolvedAt(settings, 128), std::nullopt), device, "1").specular);
    auto otherMethod = settings;
    otherMethod.samples = 64;
    const auto sampled = bakeKeys(resolvedAt(otherMethod, 256), input, plan, device, "1");
    EXPECT_NE(sampled.specular, base.specular);
    EXPECT_EQ(sampled.lut, base.lut);
}

} // namespace
} // namespace iblkit::bake
