// The whole-bake bench: every bake it times is listed with what the device computed, the cached
// bake computes nothing, each scene skips what it does not need, and the comparison with the full
// bake finds a needed level that differs and ignores one the plan fills.
#include "bake.hpp"
#include "bake_bench.hpp"
#include "ktx2.hpp"

#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

namespace iblkit::bench {
namespace {

namespace fs = std::filesystem;

const BakeTiming& row(const std::vector<BakeTiming>& rows, const std::string& bake) {
    for (const auto& timing : rows)
        if (timing.bake == bake) return timing;
    throw std::runtime_error("no row " + bake);
}

TEST(BakeBench, TimesEveryBakeAndFindsTheNeededValuesUnchanged) {
    testing::TempFolder scratch;
    BenchOptions options;
    options.repeat = 1;
    options.log = nullptr;
    const char* mesaCache = std::getenv("MESA_SHADER_CACHE_DIR");
    const std::string mesaCacheBefore = mesaCache ? mesaCache : "(unset)";
    const auto rows = benchBakes(options, {}, scratch.path());
    mesaCache = std::getenv("MESA_SHADER_CACHE_DIR");
    EXPECT_EQ(mesaCache ? mesaCache : "(unset)", mesaCacheBefore) << "the cold bake's Mesa cache folder is put back";
    ASSERT_EQ(rows.size(), 4u + 4u) << "full, first with empty caches, first, again; four scenes";
    for (const auto& timing : rows) {
        SCOPED_TRACE(timing.bake);
        EXPECT_EQ(timing.environment, "sky");
        EXPECT_TRUE(timing.identical);
        EXPECT_GT(timing.wallMilliseconds, 0);
        EXPECT_EQ(timing.fullWallMilliseconds, row(rows, "full, no cache").wallMilliseconds);
        EXPECT_EQ(timing.repeat, timing.bake == "full, no cache" ? 2u : 1u) << "the full bake's warm-up is a repeat";
    }
    const auto full = row(rows, "full, no cache").computed;
    EXPECT_EQ(full, "source cube, lights, irradiance, prefilter mips 1-5, brdf lut, preview");
    EXPECT_EQ(row(rows, "first, empty cache").computed, full);
    EXPECT_EQ(row(rows, "the same bake again").computed, "nothing");
    EXPECT_EQ(row(rows, "scene: all-mirror metal, no cache").computed,
              "source cube, lights, SH (the preview's exposure), brdf lut, preview");
    EXPECT_EQ(row(rows, "scene: unlit, no cache").computed, "source cube, lights, SH (the preview's exposure), preview");
    // Roughness 0.7 to 1 reads the kit's mips 4 (0.557) and 5 (1).
    EXPECT_NE(row(rows, "scene: rough dielectric, no cache").computed.find("prefilter mips 4-5"), std::string::npos);
}

void writeKtx2(const fs::path& path, const image_io::Texture& texture) {
    const auto bytes = image_io::encodeKtx2(texture, "test");
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

TEST(BakeBench, TheComparisonFindsANeededLevelThatDiffers) {
    testing::TempFolder scratch;
    const std::vector<float> values(6 * (4 * 4 + 2 * 2 + 1) * 4, 0.5f);
    const auto texture = image_io::makeTexture(image_io::PixelFormat::Rgba16Float, 4, 4, 6, 3, values);
    fs::create_directories(scratch.path() / "full");
    fs::create_directories(scratch.path() / "baked");
    writeKtx2(scratch.path() / "full" / "specular.ktx2", texture);
    auto changed = texture;
    changed.levels[1][5] ^= std::byte{1}; // one bit of mip 1
    writeKtx2(scratch.path() / "baked" / "specular.ktx2", changed);
    EXPECT_FALSE(neededLevelsMatch(scratch.path() / "full", scratch.path() / "baked", "specular.ktx2", {true, true, true}));
    EXPECT_FALSE(neededLevelsMatch(scratch.path() / "full", scratch.path() / "baked", "specular.ktx2", {}));
    EXPECT_TRUE(neededLevelsMatch(scratch.path() / "full", scratch.path() / "baked", "specular.ktx2", {true, false, true}))
        << "mip 1 is filled, not needed";
    EXPECT_TRUE(neededLevelsMatch(scratch.path() / "full", scratch.path() / "baked", "irradiance.ktx2", {}))
        << "a skipped output";
}

} // namespace
} // namespace iblkit::bench
