// The bake's settings: the documented defaults and the refusal of every out-of-range value.
#include "bake_error.hpp"
#include "bake_settings.hpp"
#include "texel_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace iblkit::bake {
namespace {

BakeSettings settingsWithOutput() {
    BakeSettings settings;
    settings.outputDir = "out";
    return settings;
}

// The face size and chain of `settings` for an input cube of `inputCubeSize` (0: a panorama).
ResolvedSettings resolvedFor(const BakeSettings& settings, uint32_t inputCubeSize = 0) {
    auto resolved = resolveSettings(settings);
    resolveFaceSize(resolved, inputCubeSize);
    return resolved;
}

TEST(BakeSettings, DefaultChainEndsAtEightByEightWithRoughnessOne) {
    const auto settings = settingsWithOutput();
    EXPECT_EQ(resolveSettings(settings).faceSize, 256u);
    EXPECT_EQ(resolveSettings(settings).mipCount, 6u); // 256, 128, 64, 32, 16, 8
    EXPECT_EQ(resolvedFor(settings, 8).mipCount, 1u);
    EXPECT_EQ(resolvedFor(settings, 4).mipCount, 1u);
    EXPECT_EQ(chainDownTo(256, 8), 6u);
    EXPECT_EQ(chainDownTo(256, 1), 9u);
    EXPECT_FLOAT_EQ(roughnessOfMip(0, 6), 0.f);
    EXPECT_FLOAT_EQ(roughnessOfMip(1, 6), 0.2f);
    EXPECT_FLOAT_EQ(roughnessOfMip(5, 6), 1.f);
}

TEST(BakeSettings, AProfileBringsItsRecipeAndChainAndTakesARecipeOfItsMapping) {
    auto settings = settingsWithOutput();
    settings.profile = "threejs";
    EXPECT_EQ(resolveSettings(settings).engineProfile->name, std::string("threejs"));
    EXPECT_EQ(resolveSettings(settings).shadingRecipe->name, "quadratic-lights");
    EXPECT_EQ(resolveSettings(settings).mipCount, 6u); // three.js's PMREM ends at 8²
    settings.recipe = "quadratic";                     // the same lod mapping: the engine finds its mips
    EXPECT_EQ(resolveSettings(settings).shadingRecipe->name, "quadratic");
}

TEST(BakeSettings, InputCubeSetsTheSizeAndAConflictingSizeIsRefused) {
    auto settings = settingsWithOutput();
    EXPECT_EQ(resolvedFor(settings, 128).faceSize, 128u);
    EXPECT_EQ(resolvedFor(settings, 128).mipCount, 5u);
    EXPECT_THROW(resolvedFor(settings, 96), BakeError) << "a cube's faces must be a power of two";
    settings.size = 64;
    EXPECT_THROW(resolvedFor(settings, 128), BakeError);
    settings.size = 128;
    EXPECT_EQ(resolvedFor(settings, 128).faceSize, 128u);
    // A chain asked without a size waits for the input's: a 1024² cube has 11 mips, the default 256² nine.
    settings.size.reset();
    settings.mips = 11;
    EXPECT_EQ(resolvedFor(settings, 1024).mipCount, 11u);
    EXPECT_THROW(resolvedFor(settings, 0), BakeError) << "a panorama is baked at 256²";
}

TEST(BakeSettings, EachMethodHasItsOwnDefaultCount) {
    auto settings = settingsWithOutput();
    EXPECT_EQ(settings.specularMethod, "convolution");
    EXPECT_EQ(resolveSettings(settings).sampleCount, kDefaultConvolutionBudget);
    settings.specularMethod = "pyramid";
    EXPECT_EQ(resolveSettings(settings).sampleCount, kDefaultPyramidReads);
    settings.specularMethod = "mipchain";
    EXPECT_EQ(resolveSettings(settings).sampleCount, 1u) << "it takes no count";
    settings.specularMethod = "document";
    EXPECT_EQ(resolveSettings(settings).sampleCount, 1024u);
    settings.samples = 64;
    EXPECT_EQ(resolveSettings(settings).sampleCount, 64u);
    EXPECT_EQ(settings.lutMethod, "quadrature-grid");
    EXPECT_EQ(resolveSettings(settings).lutSampleCount, kernels::kDefaultLutGrid);
    settings.lutMethod = "quadrature";
    EXPECT_EQ(resolveSettings(settings).lutSampleCount, kernels::kDefaultQuadratureNodes);
    settings.lutMethod = "document";
    EXPECT_EQ(resolveSettings(settings).lutSampleCount, 1024u);
}

TEST(BakeSettings, OutOfRangeValuesAreRefusedByName) {
    const auto refused = [](auto change, const std::string& name) {
        auto settings = settingsWithOutput();
        change(settings);
        try {
            resolveSettings(settings);
            ADD_FAILURE() << name << " was accepted";
        } catch (const BakeError& error) {
            EXPECT_NE(std::string(error.what()).find(name), std::string::npos) << error.what();
        }
    };
    refused([](BakeSettings& s) { s.size = 100; }, "--size 100 is not a power of two");
    refused([](BakeSettings& s) { s.size = 0; }, "--size");
    refused([](BakeSettings& s) { s.size = 32768; }, "--size");
    refused([](BakeSettings& s) { s.samples = 0; }, "--samples");
    refused([](BakeSettings& s) { s.samples = 65536; }, "--samples 65536 is out of range (1 to 2048)");
    refused([](BakeSettings& s) {
        s.specularMethod = "pyramid";
        s.samples = 5;
    }, "--samples 5 is out of range (1 to 4)");
    refused([](BakeSettings& s) {
        s.specularMethod = "mipchain";
        s.samples = 2;
    }, "--samples 2 is out of range (1 to 1)");
    refused([](BakeSettings& s) { s.specularMethod = "nope"; }, "--method nope is not a prefilter method (there are: document, filtered, table, pyramid, mipchain, convolution)");
    refused([](BakeSettings& s) { s.lutSize = 0; }, "--lut-size");
    refused([](BakeSettings& s) { s.lutMethod = "quadrature-grid"; s.lutSamples = 3; },
            "--lut-samples 3 is out of range (4 to 1024)");
    refused([](BakeSettings& s) { s.lutMethod = "nope"; }, "--lut-method nope is not a LUT method (there are: document, quadrature, fit, quadrature-grid)");
    refused([](BakeSettings& s) { s.lutMethod = "quadrature"; s.lutSamples = 17; }, "--lut-samples 17 is out of range (1 to 16)");
    refused([](BakeSettings& s) { s.irradianceSize = 0; }, "--irradiance-size");
    refused([](BakeSettings& s) { s.profile = "nope"; }, "--profile: no profile named 'nope' (there are: iblkit, threejs, babylon, filament, gltf)");
    refused([](BakeSettings& s) { s.profile = "threejs"; s.recipe = "kit"; },
            "--recipe kit maps roughness to lod by logarithmic, but --profile threejs reads mips by quadratic");
    refused([](BakeSettings& s) { s.profile = "threejs"; s.specularMethod = "document"; },
            "--recipe quadratic-lights prefilters a lobe weighted by G1, which only --method convolution computes");
    auto settings = settingsWithOutput();
    settings.specularMethod = "document";
    settings.samples = 65536;
    EXPECT_NO_THROW(resolveSettings(settings)) << "past the convolution's limit, not the document's";
    settings.size = 256;
    settings.mips = 10; // a 256 cube has 9
    EXPECT_THROW(resolveSettings(settings), BakeError);
}

TEST(TexelChecks, NonFiniteTexelsAreCountedWithTheFirstOneAndAlphaIsIgnored) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    std::vector<float> rgba = {1, 1, 1, nan, 2, inf, 2, 1, 3, 3, nan, 1};
    const auto found = findNonFiniteTexels(rgba, 4);
    EXPECT_EQ(found.count, 2u);
    EXPECT_EQ(found.firstTexel, 1u);
    EXPECT_TRUE(std::isinf(found.firstValue));
    EXPECT_EQ(replaceNonFiniteTexels(rgba, 4), 2u);
    const std::vector<float> colours = {rgba[0], rgba[1], rgba[2], rgba[4], rgba[5], rgba[6], rgba[8], rgba[9], rgba[10]};
    EXPECT_EQ(colours, (std::vector<float>{1, 1, 1, 0, 0, 0, 0, 0, 0}));
    EXPECT_TRUE(std::isnan(rgba[3])) << "alpha carries no light and is left alone";
}

TEST(TexelChecks, HalfOverflowIsFoundAndClamped) {
    std::vector<float> values = {1, 65504, 65520, -1e6f};
    const auto found = findHalfOverflow(values);
    EXPECT_EQ(found.count, 2u);
    EXPECT_EQ(found.firstValue, 2u);
    EXPECT_EQ(found.largest, 1e6f);
    clampToHalfRange(values);
    EXPECT_EQ(values, (std::vector<float>{1, 65504, 65504, -65504}));
}

} // namespace
} // namespace iblkit::bake
