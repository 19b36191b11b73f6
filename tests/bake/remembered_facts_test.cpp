// What a bake remembers to save time: the input's facts, so that a cached bake of a file does not
// decode it, and the device, so that a cached bake reads its entries while the real device is
// found. Neither may ever change a file: facts are kept per file and policy, and a remembered
// device that is not the real one costs time, never a wrong entry.
#include "bake.hpp"
#include "bake_cache.hpp"
#include "bake_error.hpp"
#include "float_image.hpp"
#include "remembered_facts.hpp"
#include "read_file.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace iblkit::bake {
namespace {

namespace fs = std::filesystem;

using iblkit::testing::readFile;

vulkan::DeviceInfo anotherDevice() { return {0, "another device", "cpu", "another driver", "1.3.0", false}; }

class RememberedFacts : public ::testing::Test {
protected:
    void SetUp() override {
        std::vector<float> values(64 * 32 * 3, 0.5f);
        values[7] = -0.25f; // two negative texels, which the bake clamps and reports
        values[100] = -0.125f;
        image_io::writeExr(panorama(), {64, 32, 3, values});
    }
    fs::path panorama() const { return scratch.path() / "environment.exr"; }
    fs::path cacheFolder() const { return scratch.path() / "cache"; }
    BakeSettings settings(const std::string& output) const {
        BakeSettings s;
        s.outputDir = scratch.path() / output;
        s.environment = panorama();
        s.size = 32;
        s.lutSize = 16;
        s.irradianceSize = 8;
        s.cache = cacheFolder();
        return s;
    }
    static BakeSummary bake(const BakeSettings& s) {
        BakeProgress progress(true);
        return bakeEnvironment(s, "test", progress);
    }
    static bool ran(const BakeSummary& summary, const std::string& step) {
        return std::any_of(summary.steps.begin(), summary.steps.end(), [&](const auto& each) { return each.name == step; });
    }
    iblkit::testing::TempFolder scratch;
};

TEST_F(RememberedFacts, ACachedBakeDescribesItsInputFromTheFactsKeptForIt) {
    EXPECT_EQ(bake(settings("first")).negativeTexels.count, 2u);
    cache::ContentStore store(cacheFolder());
    auto input = readEnvironment(panorama(), {});
    const auto facts = rememberedFacts(store, input);
    ASSERT_TRUE(facts) << "the first bake keeps them";
    EXPECT_EQ(facts->negative.count, 2u);
    EXPECT_EQ(facts->panoramaWidth, 64u);
    // Facts that say otherwise: a bake that shows them did not decode the file.
    decodeEnvironment(input);
    input.negative.count = 12345;
    rememberFacts(store, input);
    const auto second = bake(settings("second"));
    EXPECT_EQ(second.cache.misses, 0u);
    EXPECT_FALSE(ran(second, "decode"));
    EXPECT_EQ(second.negativeTexels.count, 12345u) << "described from the facts, not decoded";
    auto strict = settings("strict");
    strict.strict = true; // another policy has facts of its own: decoded, and refused
    EXPECT_THROW(bake(strict), BakeError);
}

TEST_F(RememberedFacts, ABakeTheCacheCannotServeDecodesTheInput) {
    bake(settings("first"));
    auto smaller = settings("smaller");
    smaller.size = 16;
    const auto summary = bake(smaller);
    EXPECT_TRUE(ran(summary, "decode")) << "the facts were there, the maps of this size were not";
    EXPECT_EQ(summary.negativeTexels.count, 2u);
    auto uncached = smaller;
    uncached.outputDir = scratch.path() / "uncached";
    uncached.cache.reset();
    bake(uncached);
    for (const char* file : {"specular.ktx2", "irradiance.ktx2", "preview.png"})
        EXPECT_EQ(readFile(scratch.path() / "smaller" / file), readFile(scratch.path() / "uncached" / file)) << file;
}

TEST_F(RememberedFacts, AWrongRememberedDeviceIsFoundOutAndForgotten) {
    const auto first = settings("first");
    bake(first);
    cache::ContentStore store(cacheFolder());
    const auto real = rememberedDevice(store, first.context);
    ASSERT_TRUE(real) << "the first bake remembers its device";
    rememberDevice(store, first.context, anotherDevice());
    const auto second = bake(settings("second"));
    EXPECT_EQ(second.cache.hits, 6u);
    EXPECT_EQ(second.cache.misses, 0u) << "the reads under the other device's keys are not counted";
    EXPECT_FALSE(ran(second, "device"));
    EXPECT_TRUE(sameIdentity(*rememberedDevice(store, first.context), *real));
}

// Every map cached under the remembered device's keys as well, but the bake runs on another
// device: what it writes is never those entries.
TEST_F(RememberedFacts, MapsCachedUnderAWrongRememberedDeviceAreNeverWritten) {
    const auto first = settings("first");
    bake(first);
    cache::ContentStore store(cacheFolder());
    BakeProgress progress(true);
    auto prepared = prepareBake(first, BakeDestination::Memory, progress);
    const auto real = *rememberedDevice(store, first.context);
    const auto keys = bakeKeys(prepared.settings, prepared.input, prepared.plan, real, "test");
    const auto others = bakeKeys(prepared.settings, prepared.input, prepared.plan, anotherDevice(), "test");
    for (const auto& [from, to] : {std::pair{keys.specular, others.specular}, {keys.lut, others.lut},
                                   {keys.irradiance, others.irradiance}, {keys.lights, others.lights},
                                   {keys.lobeTable, others.lobeTable}})
        store.put(to, *store.get(from));
    store.put(others.preview, "not this device's preview");
    rememberDevice(store, first.context, anotherDevice());

    const auto second = bake(settings("second"));
    EXPECT_EQ(readFile(scratch.path() / "first" / "preview.png"), readFile(scratch.path() / "second" / "preview.png"));
    EXPECT_EQ(second.cache.hits, 6u);
    EXPECT_EQ(second.cache.misses, 0u);
    EXPECT_TRUE(sameIdentity(*rememberedDevice(store, first.context), real));
    EXPECT_EQ(std::count_if(fs::directory_iterator(scratch.path()), fs::directory_iterator(),
                            [](const auto& entry) { return entry.path().filename().string().starts_with(".iblkit-partial"); }),
              0) << "no staging folder left beside the output";
}

} // namespace
} // namespace iblkit::bake
