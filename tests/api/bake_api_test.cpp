// iblkit::bakeToMemory and iblkit::bakeToFolder as a program calls them, on one small bake of the
// built-in sky each: the maps in memory are the ones the folder's files hold (read back with the
// kit's KTX2 reader), and the LUT is the converged double quadrature's.
#include <iblkit/iblkit.hpp>

#include "converged_lut.hpp"
#include "files.hpp"
#include "ktx2.hpp"
#include "read_file.hpp"
#include "texture.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <set>
#include <unistd.h>

namespace iblkit {
namespace {

namespace fs = std::filesystem;

// 32² faces (3 mips down to the kit's 8²), a 16² LUT, an 8² irradiance cube: the kit's defaults
// otherwise (the convolution, the kit's recipe with its lights taken out), and no cache.
BakeRequest smallSkyBake() {
    BakeRequest request;
    request.size = 32;
    request.lutSize = 16;
    request.irradianceSize = 8;
    return request;
}

class BakeApi : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        scratch_ = fs::temp_directory_path() / ("iblkit-api-bake-" + std::to_string(::getpid()));
        fs::remove_all(scratch_);
        maps_ = new BakedMaps(bakeToMemory(smallSkyBake()));
        summary_ = new BakeSummary(bakeToFolder(smallSkyBake(), scratch_ / "out"));
    }
    static void TearDownTestSuite() {
        delete maps_;
        delete summary_;
        fs::remove_all(scratch_);
    }
    static fs::path out(const std::string& name) { return scratch_ / "out" / name; }
    static const BakedMaps& maps() { return *maps_; }
    static const BakeSummary& summary() { return *summary_; }

private:
    static fs::path scratch_;
    static BakedMaps* maps_;
    static BakeSummary* summary_;
};
fs::path BakeApi::scratch_;
BakedMaps* BakeApi::maps_ = nullptr;
BakeSummary* BakeApi::summary_ = nullptr;

image_io::Texture readKtx2(const fs::path& path) {
    return image_io::decodeKtx2(image_io::readFileBytes(path), path.string());
}

// Every mip's faces in turn: the order of the KTX2 file's values.
std::vector<float> valuesOf(const std::vector<CubeMip>& mips) {
    std::vector<float> values;
    for (const auto& mip : mips)
        for (const auto& face : mip.faces) values.insert(values.end(), face.begin(), face.end());
    return values;
}

// What the file holds for these values: 16-bit floats, rounded by the writer's own conversion.
std::vector<float> asWritten(const image_io::Texture& file, const std::vector<float>& values) {
    return image_io::textureValues(image_io::makeTexture(file.format, file.width, file.height, file.faces, file.mips, values));
}

TEST_F(BakeApi, TheMapsHaveTheShapesAsked) {
    ASSERT_EQ(maps().specular.size(), 3u);
    for (uint32_t mip = 0; mip < 3; ++mip) {
        EXPECT_EQ(maps().specular[mip].size, 32u >> mip);
        for (const auto& face : maps().specular[mip].faces) EXPECT_EQ(face.size(), size_t(4) * (32 >> mip) * (32 >> mip));
    }
    EXPECT_EQ(maps().specularRoughness.size(), 3u);
    EXPECT_EQ(maps().specularRoughness.front(), 0.f);
    EXPECT_EQ(maps().specularRoughness.back(), 1.f);
    EXPECT_EQ(maps().brdfLut.width, 16u);
    EXPECT_EQ(maps().brdfLut.channels, 2u);
    EXPECT_EQ(maps().brdfLut.values.size(), 16u * 16u * 2u);
    EXPECT_EQ(maps().irradiance.size, 8u);
    EXPECT_FALSE(maps().lights.empty()) << "the kit's recipe takes the sky's sun out";
    EXPECT_FALSE(maps().lobeTable.values.empty()) << "the kit's recipe reads its lobe through the table";
    EXPECT_FALSE(maps().device.empty());
    EXPECT_TRUE(maps().validationMessages.empty());
    EXPECT_EQ(nlohmann::json::parse(maps().shading).at("recipe"), "kit");
}

TEST_F(BakeApi, TheFolderHoldsTheFilesOfTheCommandLinesBake) {
    EXPECT_EQ(summary().folder.filename(), "out");
    std::set<std::string> names;
    for (const auto& file : summary().files) names.insert(file.name);
    for (const char* name : {"specular.ktx2", "brdf_lut.ktx2", "irradiance.ktx2", "lobe_table.ktx2", "preview.png",
                             "lights.gltf", "manifest.json"}) {
        EXPECT_TRUE(names.count(name)) << name;
        EXPECT_TRUE(fs::exists(out(name))) << name;
    }
    EXPECT_TRUE(summary().halfRangeClamps.empty()) << "the sky's sun at 32² stays within the half range";
    EXPECT_EQ(nlohmann::json::parse(summary().json).at("files").size(), summary().files.size());
    EXPECT_EQ(summary().device, maps().device);
}

// The device computes the same values for the same bake: the files are the maps, rounded to
// their 16-bit floats by the writer's conversion, exactly.
TEST_F(BakeApi, TheMapsInMemoryAreTheFilesOfTheFolderBake) {
    const auto specular = readKtx2(out("specular.ktx2"));
    EXPECT_EQ(image_io::textureValues(specular), asWritten(specular, valuesOf(maps().specular)));
    const auto irradiance = readKtx2(out("irradiance.ktx2"));
    EXPECT_EQ(image_io::textureValues(irradiance), asWritten(irradiance, valuesOf({maps().irradiance})));
    const auto lut = readKtx2(out("brdf_lut.ktx2"));
    EXPECT_EQ(image_io::textureValues(lut), asWritten(lut, maps().brdfLut.values));
    EXPECT_EQ(image_io::textureValues(readKtx2(out("lobe_table.ktx2"))), maps().lobeTable.values) << "RGBA32F: no rounding";
}

TEST_F(BakeApi, TheRoughnessLightsAndShAreTheManifestsAndTheLightFiles) {
    const auto manifest = nlohmann::json::parse(testing::readFile(out("manifest.json")));
    EXPECT_EQ(manifest.at("specular").at("roughness").get<std::vector<float>>(), maps().specularRoughness);
    EXPECT_EQ(summary().shRadiance, maps().shRadiance);
    const auto gltf = nlohmann::json::parse(testing::readFile(out("lights.gltf")));
    const auto& lights = gltf.at("extensions").at("KHR_lights_punctual").at("lights");
    ASSERT_EQ(lights.size(), maps().lights.size());
    for (size_t i = 0; i < lights.size(); ++i) {
        const auto& extras = lights[i].at("extras");
        EXPECT_EQ(extras.at("direction").get<std::vector<double>>(),
                  std::vector<double>(maps().lights[i].direction.begin(), maps().lights[i].direction.end()));
        EXPECT_EQ(extras.at("radiance").get<std::vector<double>>(),
                  std::vector<double>(maps().lights[i].radiance.begin(), maps().lights[i].radiance.end()));
        EXPECT_EQ(extras.at("angular_radius").get<double>(), maps().lights[i].angularRadius);
    }
}

// Column x at N·V = (x + 0.5) / 16, row y at roughness (y + 0.5) / 16, against the converged double
// quadrature (reference/converged_lut.hpp, converged to about 1e-13). Measured 1.8e-6 on lavapipe:
// the default quadrature grid's interpolation and float arithmetic (9.7e-6 at 256², tests/kernels);
// bound 4e-6, about twice that.
constexpr double kLutBound = 4e-6;

TEST_F(BakeApi, TheLutIsTheConvergedQuadrature) {
    const auto converged = reference::convergedBrdfLut(16);
    const auto& lut = maps().brdfLut.values;
    double worst = 0;
    for (size_t i = 0; i < lut.size(); ++i) worst = std::max(worst, std::abs(lut[i] - converged[i]));
    std::ostringstream text;
    text << std::setprecision(3) << worst;
    RecordProperty("lut_max_abs_error", text.str());
    EXPECT_LT(worst, kLutBound);
    // One texel by hand: N·V = 0.53125, roughness 0.53125 (column 8, row 8).
    const auto texel = reference::convergedBrdf(8.5 / 16, 8.5 / 16);
    EXPECT_NEAR(lut[(8 * 16 + 8) * 2], texel.x, kLutBound);
    EXPECT_NEAR(lut[(8 * 16 + 8) * 2 + 1], texel.y, kLutBound);
}

} // namespace
} // namespace iblkit
