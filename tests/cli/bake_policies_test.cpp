// What real HDRIs bring to `iblkit bake`: negative texels and an unclipped sun bake by default,
// reported on stderr, in --json and in the manifest, and --strict refuses them; a texel whose sums
// would overflow a float is refused by name; the preview's exposure stays finite and positive.
#include "bake_cli_fixture.hpp"
#include "float_image.hpp"

#include <nlohmann/json.hpp>

namespace iblkit::testing {
namespace {

constexpr uint32_t kWidth = 16, kHeight = 8;

class BakePolicies : public BakeCli {
protected:
    // A flat panorama of `value` with `changes` (texel index, value) written to every channel.
    void writePanorama(const std::string& name, float value, const std::vector<std::pair<uint32_t, float>>& changes) {
        image_io::FloatImage image{kWidth, kHeight, 3, std::vector<float>(kWidth * kHeight * 3, value)};
        for (const auto& [texel, changed] : changes)
            for (int c = 0; c < 3; ++c) image.values[texel * 3 + c] = changed;
        image_io::writeExr(scratch.path() / name, image);
    }
    nlohmann::json manifest(const std::string& folder) const {
        return nlohmann::json::parse(readFile(scratch.path() / folder / "manifest.json"));
    }
};

TEST_F(BakePolicies, AnUnclippedSunBakesAndReportsWhatTheClampCost) {
    writePanorama("sun.exr", 1.f, {{4 * kWidth + 4, 1e6f}});
    const auto result = iblkit(small({"bake", at("sun.exr"), "-o", at("out"), "--json"}));
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_NE(result.err.find("warning: clamped"), std::string::npos) << result.err;
    const auto summary = nlohmann::json::parse(result.out);
    EXPECT_GT(summary["clamped_values"].get<int>(), 0);
    const auto& specular = summary["half_range_clamps"].at(0);
    EXPECT_EQ(specular["texture"], "specular");
    EXPECT_EQ(specular["worst_mip"], 0) << "mips 1 and up are prefiltered from the 32-bit source";
    // The sun is most of mip 0's energy: 1e6 against 127 texels of 1 on the panorama.
    EXPECT_GT(specular["share_of_its_energy_lost"].get<double>(), 0.5);
    EXPECT_LT(specular["share_of_its_energy_lost"].get<double>(), 1.0);
    const auto halfRange = manifest("out")["half_range"];
    EXPECT_EQ(halfRange["policy"], "clamp to 65504");
    EXPECT_EQ(halfRange["clamped_values"], summary["clamped_values"]);
    expectFailure(small({"bake", at("sun.exr"), "-o", at("strict"), "--strict"}), "bake without --strict to clamp them");
}

TEST_F(BakePolicies, NegativeTexelsAreClampedToZeroAndReported) {
    writePanorama("negative.exr", 1.f, {{5, -7.5e-4f}, {40, -2e-5f}});
    const auto result = iblkit(small({"bake", at("negative.exr"), "-o", at("out"), "--json"}));
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_NE(result.err.find("clamped 2 input texels of negative radiance to 0, down to -0.00075"), std::string::npos)
        << result.err;
    const auto summary = nlohmann::json::parse(result.out);
    EXPECT_EQ(summary["negative_texels"], 2);
    EXPECT_FLOAT_EQ(summary["most_negative"].get<float>(), -7.5e-4f);
    const auto negative = manifest("out")["input"]["negative_radiance"];
    EXPECT_EQ(negative["policy"], "clamp to 0");
    EXPECT_EQ(negative["texels"], 2);
    expectFailure(small({"bake", at("negative.exr"), "-o", at("strict"), "--strict"}),
                  "has 2 texels of negative radiance (down to -0.00075); bake without --strict");
}

TEST_F(BakePolicies, ATexelWhoseSumsWouldOverflowIsRefusedByName) {
    writePanorama("huge.exr", 1.f, {{2 * kWidth + 5, 1e37f}});
    expectFailure(small({"bake", at("huge.exr"), "-o", at("out")}), "has a texel of 1e+37 at column 5, row 2");
    writePanorama("large.exr", 1.f, {{2 * kWidth + 5, 1e19f}});
    const auto result = iblkit(small({"bake", at("large.exr"), "-o", at("out")}));
    EXPECT_EQ(result.exitCode, 0) << "1e19 is below the limit of 1e20 and bakes:\n" << result.err;
}

TEST_F(BakePolicies, ThePreviewExposureStaysFiniteAndPositive) {
    writePanorama("negative.exr", -1.f, {});
    ASSERT_EQ(iblkit(small({"bake", at("negative.exr"), "-o", at("negative")})).exitCode, 0);
    EXPECT_EQ(manifest("negative")["preview"]["exposure"], 1.0) << "all clamped to 0: a black environment";
    writePanorama("dim.exr", 1e-30f, {});
    ASSERT_EQ(iblkit(small({"bake", at("dim.exr"), "-o", at("dim")})).exitCode, 0);
    EXPECT_EQ(manifest("dim")["preview"]["exposure"], double(1 << 30)) << "0.4 / 1e-30, held at 2^30";
}

} // namespace
} // namespace iblkit::testing
