// A bake of the built-in environment read back from its files and checked against the C++
// reference, a white-furnace bake, and the conversion's orientation against an analytic sky.
#include "bake.hpp"
#include "kernels/convolution_method.hpp"
#include "converged_prefilter.hpp"
#include "float_image.hpp"
#include "files.hpp"
#include "ktx2.hpp"
#include "ktx2_validator.hpp"
#include "dds_validator.hpp"
#include "reference_bake.hpp"
#include "reference_irradiance.hpp"
#include "sha256.hpp"
#include "temp_folder.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace iblkit::bake {
namespace {

namespace fs = std::filesystem;

struct Decoded {
    image_io::Texture texture;
    std::vector<float> values;
};

Decoded readKtx2(const fs::path& path) {
    const auto bytes = image_io::readFileBytes(path);
    const auto violations = iblkit::testing::validateKtx2(bytes);
    for (const auto& violation : violations) ADD_FAILURE() << path << ": " << violation;
    auto texture = image_io::decodeKtx2(bytes, path.string());
    auto values = image_io::textureValues(texture);
    return {std::move(texture), std::move(values)};
}

// The largest |a - b| / max(|b|, floor) over RGB of matching texels.
double maxRelativeError(const float* gpu, const float* reference, size_t texels, size_t gpuStride, size_t referenceStride,
                        double floor) {
    double worst = 0;
    for (size_t t = 0; t < texels; ++t)
        for (size_t c = 0; c < 3; ++c) {
            const double a = gpu[t * gpuStride + c], b = reference[t * referenceStride + c];
            worst = std::max(worst, std::abs(a - b) / std::max(std::abs(b), floor));
        }
    return worst;
}

vulkan::ContextOptions validatedContext(std::shared_ptr<vulkan::ValidationLog> log) {
    vulkan::ContextOptions options;
    options.validation = true;
    options.validationLog = std::move(log);
    return options;
}

void expectNoValidationMessages(const vulkan::ValidationLog& log) {
    for (const auto& message : log.messages()) ADD_FAILURE() << "validation: " << message;
}

// One bake of the built-in environment shared by the suite: 64² faces (4 mips down to 8²),
// the documents' prefilter at 256 samples, a 32² LUT, a 16² irradiance cube, every output format.
class BuiltInBake : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        folder_ = fs::temp_directory_path() / ("iblkit-bake-test-" + std::to_string(::getpid()));
        fs::remove_all(folder_);
        BakeSettings settings;
        settings.outputDir = folder_ / "out";
        settings.size = 64;
        settings.specularMethod = "document"; // the convolution has its own suite below
        settings.samples = 256;
        settings.lutSize = 32;
        settings.lutMethod = "document"; // tests/kernels checks the default LUT against the converged one
        settings.lutSamples = 256;
        settings.irradianceSize = 16;
        settings.dds = settings.exr = true;
        auto log = std::make_shared<vulkan::ValidationLog>();
        settings.context = validatedContext(log);
        BakeProgress progress(true);
        summary_ = new BakeSummary(bakeEnvironment(settings, "test", progress));
        validationMessages_ = log->messages();
    }
    static void TearDownTestSuite() {
        delete summary_;
        fs::remove_all(folder_);
    }
    static fs::path out(const std::string& name) { return folder_ / "out" / name; }

    static fs::path folder_;
    static BakeSummary* summary_;
    static std::vector<std::string> validationMessages_;
};
fs::path BuiltInBake::folder_;
BakeSummary* BuiltInBake::summary_ = nullptr;
std::vector<std::string> BuiltInBake::validationMessages_;

TEST_F(BuiltInBake, RunsCleanUnderTheValidationLayer) {
    for (const auto& message : validationMessages_) ADD_FAILURE() << "validation: " << message;
}

TEST_F(BuiltInBake, WritesEveryFileTheManifestListsWithItsHash) {
    std::ifstream stream(out("manifest.json"));
    const auto manifest = nlohmann::json::parse(stream);
    EXPECT_EQ(manifest["generator"], "iblkit");
    EXPECT_EQ(manifest["command"], "bake");
    EXPECT_EQ(manifest["input"]["kind"], "built-in");
    std::set<std::string> names;
    for (const auto& file : manifest["files"]) {
        const std::string name = file["name"];
        names.insert(name);
        EXPECT_EQ(file["sha256"], cache::sha256OfFile(out(name))) << name;
        EXPECT_EQ(file["bytes"], fs::file_size(out(name))) << name;
    }
    for (const char* name : {"specular.ktx2", "brdf_lut.ktx2", "irradiance.ktx2", "preview.png", "specular.dds",
                             "brdf_lut.dds", "irradiance.dds", "exr/specular_mip0_px.exr", "exr/specular_mip3_nz.exr",
                             "exr/brdf_lut.exr", "exr/irradiance_py.exr"})
        EXPECT_TRUE(names.count(name)) << name << " is not in the manifest";
    EXPECT_EQ(manifest["specular"]["roughness"], nlohmann::json::parse("[0.0, 0.3333333432674408, 0.6666666865348816, 1.0]"));
}

TEST_F(BuiltInBake, KtxFilesHaveTheDocumentedShapes) {
    const auto specular = readKtx2(out("specular.ktx2")).texture;
    EXPECT_EQ(specular.format, image_io::PixelFormat::Rgba16Float);
    EXPECT_EQ(specular.faces, 6u);
    EXPECT_EQ(specular.width, 64u);
    EXPECT_EQ(specular.mips, 4u);
    const auto lut = readKtx2(out("brdf_lut.ktx2")).texture;
    EXPECT_EQ(lut.format, image_io::PixelFormat::Rg16Float);
    EXPECT_EQ(lut.faces, 1u);
    EXPECT_EQ(lut.width, 32u);
    const auto irradiance = readKtx2(out("irradiance.ktx2")).texture;
    EXPECT_EQ(irradiance.faces, 6u);
    EXPECT_EQ(irradiance.width, 16u);
    EXPECT_EQ(irradiance.mips, 1u);
}

TEST_F(BuiltInBake, DdsFilesAreWellFormed) {
    for (const char* name : {"specular.dds", "brdf_lut.dds", "irradiance.dds"}) {
        const auto violations = iblkit::testing::validateDds(image_io::readFileBytes(out(name)));
        for (const auto& violation : violations) ADD_FAILURE() << name << ": " << violation;
    }
}

// Specular mips against PrefilterSpecularCS in C++ (float), reading the file's mip 0 as the
// GPU read its float source. Measured 7.4e-4: half rounding of the input and of the output
// (2^-11 = 4.9e-4 each, at most) plus float differences; bound 1.5e-3, twice that.
TEST_F(BuiltInBake, SpecularMipsMatchTheReferencePrefilter) {
    const auto specular = readKtx2(out("specular.ktx2"));
    const uint32_t size = 64;
    std::vector<float> mip0(specular.values.begin(), specular.values.begin() + size_t(6) * size * size * 4);
    const reference::CubeEnvironment environment(size, mip0);
    size_t offset = mip0.size();
    for (uint32_t mip = 1; mip < 4; ++mip) {
        const uint32_t mipSize = size >> mip;
        const auto expected = reference::referencePrefilter<float>(environment, float(mip) / 3, mipSize, 256);
        const double error = maxRelativeError(specular.values.data() + offset, expected.data(),
                                              size_t(6) * mipSize * mipSize, 4, 4, 0.05);
        RecordProperty("specular_mip" + std::to_string(mip) + "_max_relative_error", std::to_string(error));
        EXPECT_LT(error, 1.5e-3) << "mip " << mip;
        offset += size_t(6) * mipSize * mipSize * 4;
    }
}

// The LUT against the double reference at its 32² texels. Measured 2.4e-4: half rounding
// (2^-12 for values below 1) on top of the shader's float error (2.2e-5, docs/consistency.md);
// bound 5e-4, twice that.
TEST_F(BuiltInBake, LutMatchesTheDoubleReference) {
    const auto lut = readKtx2(out("brdf_lut.ktx2"));
    const auto expected = reference::referenceBrdfLut<double>(32, 256);
    double worst = 0;
    for (size_t i = 0; i < expected.size(); ++i) worst = std::max(worst, std::abs(lut.values[i] - expected[i]));
    RecordProperty("lut_max_abs_error", std::to_string(worst));
    EXPECT_LT(worst, 5e-4);
}

// Irradiance and SH against their double references over the same source (the file's mip 0):
// the cube from the moments of its 32² mip, each summed from mip 0's 2 x 2 texels. Measured: cube
// 5.3e-4 relative (the output's half rounding, 2^-11, and the input's), SH 3.1e-5 relative to
// L00 (sums of half-rounded inputs, whose errors average out); bounds twice those, 1.1e-3 and 6.2e-5.
TEST_F(BuiltInBake, IrradianceCubeAndShMatchTheReference) {
    const auto specular = readKtx2(out("specular.ktx2"));
    std::vector<float> mip0(specular.values.begin(), specular.values.begin() + size_t(6) * 64 * 64 * 4);

    const auto irradiance = readKtx2(out("irradiance.ktx2"));
    const auto expected = reference::irradianceFromMoments(reference::irradianceMoments(mip0, 64, 32), 32, 16);
    std::vector<float> expectedFloats;
    for (const auto& e : expected) expectedFloats.insert(expectedFloats.end(), {float(e.r), float(e.g), float(e.b)});
    const double cubeError = maxRelativeError(irradiance.values.data(), expectedFloats.data(), expected.size(), 4, 3, 0.05);
    RecordProperty("irradiance_max_relative_error", std::to_string(cubeError));
    EXPECT_LT(cubeError, 1.1e-3);

    std::ifstream stream(out("manifest.json"));
    const auto manifest = nlohmann::json::parse(stream);
    const auto sh = manifest["irradiance"]["sh"]["radiance"];
    const auto expectedSh = reference::projectOnSh(mip0, 64);
    const double scale = glm::length(expectedSh[0]);
    double shError = 0;
    for (size_t k = 0; k < 9; ++k)
        for (int c = 0; c < 3; ++c) shError = std::max(shError, std::abs(sh[k][c].get<double>() - expectedSh[k][c]) / scale);
    RecordProperty("sh_max_error_relative_to_l00", std::to_string(shError));
    EXPECT_LT(shError, 6.2e-5);
}

// A constant environment must come out constant everywhere: every mip at every roughness,
// the irradiance cube, and SH with only L00 = L sqrt(4 pi). 2.5 is exact in half.
TEST(WhiteFurnaceBake, ConstantEnvironmentGivesConstantOutputs) {
    iblkit::testing::TempFolder scratch;
    image_io::writeExr(scratch.path() / "white.exr", {64, 32, 3, std::vector<float>(64 * 32 * 3, 2.5f)});
    BakeSettings settings;
    settings.environment = scratch.path() / "white.exr";
    settings.outputDir = scratch.path() / "out";
    settings.size = 32;
    settings.samples = 128;
    settings.lutSize = 8;
    settings.irradianceSize = 8;
    auto log = std::make_shared<vulkan::ValidationLog>();
    settings.context = validatedContext(log);
    BakeProgress progress(true);
    const auto summary = bakeEnvironment(settings, "test", progress);
    expectNoValidationMessages(*log);

    for (const char* name : {"specular.ktx2", "irradiance.ktx2"}) {
        const auto decoded = readKtx2(scratch.path() / "out" / name);
        double worst = 0;
        for (size_t i = 0; i < decoded.values.size(); i += 4)
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(decoded.values[i + c] - 2.5));
        // Measured 0 for the specular chain (its weights normalise exactly); the irradiance sum
        // of 6x32² float terms rounds to within 1 half ULP of 2.5 (0.002).
        EXPECT_LE(worst, 0.002) << name;
    }
    const auto& sh = summary.shRadiance;
    EXPECT_NEAR(sh[0][0], 2.5 * std::sqrt(4 * M_PI), 1e-4);
    for (size_t k = 1; k < 9; ++k)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(sh[k][c], 0, 1e-5) << "coefficient " << k;
}

// The largest relative error per channel of the file's mips 1 to 3 against the converged
// integral of its own mip 0 (half-rounded, as the GPU's float source is not: 2^-11 at most, far
// below the bounds) at each mip's roughness from the manifest, by the recipe's lobe.
std::vector<double> convolutionErrors(const BakeSettings& base, const fs::path& folder, bool g1) {
    BakeSettings settings = base;
    settings.outputDir = folder;
    settings.size = 64;
    settings.lutSize = 8;
    settings.irradianceSize = 8;
    BakeProgress progress(true);
    bakeEnvironment(settings, "test", progress);
    const auto specular = readKtx2(folder / "specular.ktx2");
    const auto roughness = nlohmann::json::parse(std::ifstream(folder / "manifest.json")).at("specular").at("roughness");
    const uint32_t size = 64;
    const std::span<const float> mip0(specular.values.data(), size_t(6) * size * size * 4);
    size_t offset = mip0.size();
    std::vector<double> errors;
    for (uint32_t mip = 1; mip < 4; ++mip) {
        const uint32_t mipSize = size >> mip;
        const auto texels = reference::seededPrefilterTexels(mipSize, 128, mip);
        const auto truth = reference::convergedPrefilter(mip0, size, roughness.at(mip).get<double>(), mipSize, texels, {1, g1});
        double worst = 0;
        for (size_t i = 0; i < texels.size(); ++i) {
            const float* at = specular.values.data() + offset +
                              ((size_t(texels[i].face) * mipSize + texels[i].y) * mipSize + texels[i].x) * 4;
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(at[c] - truth[i][c]) / truth[i][c]);
        }
        errors.push_back(worst);
        offset += size_t(6) * mipSize * mipSize * 4;
    }
    return errors;
}

// The convolution for the documents' N·L lobe at their roughness m / (mips - 1).
TEST(ConvolutionBake, MipsAreCloseToTheConvergedIntegral) {
    iblkit::testing::TempFolder scratch;
    BakeSettings settings;
    settings.recipe = "document";
    const auto errors = convolutionErrors(settings, scratch.path() / "out", false);
    for (uint32_t mip = 1; mip < 4; ++mip) {
        RecordProperty("convolution_mip" + std::to_string(mip) + "_max_relative_error", std::to_string(errors[mip - 1]));
        // Measured 9.7e-3, 1.4e-2 and 9.1e-3 per channel (mips 1 to 3, 128 terms per texel): the
        // method's own error, not rounding; bound 3e-2, twice the largest.
        EXPECT_LT(errors[mip - 1], 3e-2) << "mip " << mip;
    }
}

// The largest budget the kit takes: its walk stays within llvmpipe's 65535 loop iterations an
// invocation (all loops together, for a SIMD vector of texels), which ends every loop past them
// without a word.
// Measured 2.2e-3, 2.5e-3 and 7.2e-3 (mips 1 to 3) at 2048 terms: closer than at 128; bound
// 1.5e-2, twice the largest. At the former largest budget, 32768, the walk ran past the device's
// budget and mip 1 came out 14 times the integral.
constexpr double kLargestBudgetBound = 1.5e-2;

TEST(ConvolutionBake, AtTheLargestBudgetTheWalkStaysWithinTheDevicesLoopBudget) {
    iblkit::testing::TempFolder scratch;
    BakeSettings settings;
    settings.recipe = "document";
    settings.samples = kernels::kMaxConvolutionBudget;
    const auto errors = convolutionErrors(settings, scratch.path() / "out", false);
    for (uint32_t mip = 1; mip < 4; ++mip) {
        RecordProperty("largest_budget_mip" + std::to_string(mip) + "_max_relative_error", std::to_string(errors[mip - 1]));
        EXPECT_LT(errors[mip - 1], kLargestBudgetBound) << "mip " << mip;
    }
}

// The default bake, the kit's recipe: its G1 lobe at its logarithmic roughness, from the
// environment without its sun (the file's mip 0).
TEST(ConvolutionBake, TheKitsMipsAreCloseToTheConvergedG1Integral) {
    iblkit::testing::TempFolder scratch;
    const auto errors = convolutionErrors(BakeSettings{}, scratch.path() / "out", true);
    for (uint32_t mip = 1; mip < 4; ++mip) {
        RecordProperty("kit_mip" + std::to_string(mip) + "_max_relative_error", std::to_string(errors[mip - 1]));
        // Measured 7.6e-3, 1.4e-2 and 5.4e-3 per channel; bound 3e-2, twice the largest. Against
        // the N·L integral mips 2 and 3 are off by 11 % and 9 %: the test tells the lobes apart.
        EXPECT_LT(errors[mip - 1], 3e-2) << "mip " << mip;
    }
}

} // namespace
} // namespace iblkit::bake
