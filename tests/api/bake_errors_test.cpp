// A bake's refusals as iblkit::Error of their kind, each with its one-line message and nothing
// written; and the request's defaults are the bake's.
#include <iblkit/iblkit.hpp>

#include "api/bake_settings_of.hpp"
#include "read_file.hpp"
#include "temp_folder.hpp"
#include "thrown_error.hpp"

#include <gtest/gtest.h>

namespace iblkit {
namespace {

namespace fs = std::filesystem;

using testing::errorOf;

TEST(BakeErrors, AnEnvironmentThatIsNotThereIsBadInputAndWritesNothing) {
    testing::TempFolder scratch;
    BakeRequest request;
    request.environment = scratch.path() / "missing.hdr";
    const std::string expected = "cannot open '" + request.environment->string() + "': No such file or directory";
    EXPECT_EQ(errorOf([&] { bakeToFolder(request, scratch.path() / "out"); }),
              std::pair(ErrorKind::BadInput, expected));
    EXPECT_TRUE(fs::is_empty(scratch.path())) << "neither the folder nor its staging folder is left";
    EXPECT_EQ(errorOf([&] { bakeToMemory(request); }), std::pair(ErrorKind::BadInput, expected));
    EXPECT_TRUE(fs::is_empty(scratch.path()));
}

TEST(BakeErrors, ASettingOutOfRangeIsBadInput) {
    BakeRequest request;
    request.size = 48;
    EXPECT_EQ(errorOf([&] { bakeToMemory(request); }),
              std::pair(ErrorKind::BadInput,
                        std::string("--size 48 is not a power of two (each mip must halve the one above it exactly)")));
}

TEST(BakeErrors, AFolderOfOtherFilesIsRefusedAndKept) {
    testing::TempFolder scratch;
    const auto mine = scratch.write("out/notes.txt", "mine");
    BakeRequest request;
    request.size = 8;
    const auto [kind, message] = errorOf([&] { bakeToFolder(request, scratch.path() / "out"); });
    EXPECT_EQ(kind, ErrorKind::BadInput);
    EXPECT_NE(message.find("is a folder with other files"), std::string::npos) << message;
    EXPECT_EQ(testing::readFile(mine), "mine");
}

TEST(BakeErrors, ADeviceThatIsNotThereIsDeviceFailed) {
    BakeRequest request;
    request.size = 8;
    request.lutSize = 8;
    request.irradianceSize = 4;
    request.device = "no-such-device";
    EXPECT_EQ(errorOf([&] { bakeToMemory(request); }),
              std::pair(ErrorKind::DeviceFailed, std::string("no Vulkan device matches 'no-such-device' (see iblkit devices)")));
}

// The request's defaults, spelled in the public header, are the bake's own.
TEST(BakeErrors, TheRequestsDefaultsAreTheBakesDefaults) {
    const auto settings = api::bakeSettingsOf(BakeRequest{});
    const bake::BakeSettings defaults;
    EXPECT_EQ(settings.environment, defaults.environment);
    EXPECT_EQ(settings.scene, defaults.scene);
    EXPECT_EQ(settings.cache, defaults.cache);
    EXPECT_EQ(settings.size, defaults.size);
    EXPECT_EQ(settings.mips, defaults.mips);
    EXPECT_EQ(settings.specularMethod, defaults.specularMethod);
    EXPECT_EQ(settings.samples, defaults.samples);
    EXPECT_EQ(settings.recipe, defaults.recipe);
    EXPECT_EQ(settings.profile, defaults.profile);
    EXPECT_EQ(settings.lutSize, defaults.lutSize);
    EXPECT_EQ(settings.lutMethod, defaults.lutMethod);
    EXPECT_EQ(settings.lutSamples, defaults.lutSamples);
    EXPECT_EQ(settings.lutFormat, defaults.lutFormat);
    EXPECT_EQ(settings.irradianceSize, defaults.irradianceSize);
    EXPECT_EQ(settings.dds, defaults.dds);
    EXPECT_EQ(settings.exr, defaults.exr);
    EXPECT_EQ(settings.sanitize, defaults.sanitize);
    EXPECT_EQ(settings.strict, defaults.strict);
    EXPECT_EQ(settings.context.device, defaults.context.device);
    EXPECT_EQ(settings.context.validation, defaults.context.validation);
}

} // namespace
} // namespace iblkit
