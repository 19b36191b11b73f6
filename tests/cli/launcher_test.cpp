// The launcher `iblkit` (tools/iblkit/launcher.c) in front of a stand-in program that prints what it
// was given: the same arguments and exit status, glibc's huge-page tunable added to the user's own,
// and the program found beside the launcher or where it is installed.
#include "run_process.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace iblkit::testing {
namespace {

namespace fs = std::filesystem;

// Prints GLIBC_TUNABLES, then each argument on a line of its own, and exits with status 3.
constexpr const char* kStandIn = "#!/bin/sh\necho \"tunables=$GLIBC_TUNABLES\"\nfor a in \"$@\"; do echo \"[$a]\"; done\nexit 3\n";

class Launcher : public ::testing::Test {
protected:
    // The launcher copied to `bin`, with the stand-in at `programPath` (relative to the folder).
    fs::path install(const fs::path& programPath) const {
        const auto bin = folder.path() / "bin";
        fs::create_directories(bin);
        fs::copy_file(IBLKIT_EXECUTABLE, bin / "iblkit");
        if (!programPath.empty()) {
            fs::create_directories((folder.path() / programPath).parent_path());
            std::ofstream(folder.path() / programPath) << kStandIn;
            fs::permissions(folder.path() / programPath, fs::perms::owner_all);
        }
        return bin / "iblkit";
    }

    TempFolder folder;
};

TEST_F(Launcher, StartsTheProgramBesideItWithHugePagesAndItsArgumentsAndExitStatus) {
    const auto launcher = install("bin/iblkit-program");
    const auto result = runProcess({launcher.string(), "bake", "a file with spaces", "", "--json"}, {"GLIBC_TUNABLES="});
    EXPECT_EQ(result.exitCode, 3);
    EXPECT_EQ(result.out, "tunables=glibc.malloc.hugetlb=1\n[bake]\n[a file with spaces]\n[]\n[--json]\n");
    EXPECT_EQ(result.err, "");
}

TEST_F(Launcher, AddsTheTunableToAUsersOwnAndKeepsAUsersChoiceOfIt) {
    const auto launcher = install("bin/iblkit-program");
    EXPECT_EQ(runProcess({launcher.string()}, {"GLIBC_TUNABLES=glibc.malloc.arena_max=2"}).out,
              "tunables=glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1\n");
    EXPECT_EQ(runProcess({launcher.string()}, {"GLIBC_TUNABLES=glibc.malloc.hugetlb=0"}).out,
              "tunables=glibc.malloc.hugetlb=0\n");
}

TEST_F(Launcher, FindsTheInstalledProgramUnderLibexec) {
    const auto launcher = install("libexec/iblkit/iblkit-program");
    const auto result = runProcess({launcher.string(), "--version"}, {"GLIBC_TUNABLES="});
    EXPECT_EQ(result.exitCode, 3);
    EXPECT_EQ(result.out, "tunables=glibc.malloc.hugetlb=1\n[--version]\n");
}

TEST_F(Launcher, AMissingProgramIsOneLineAndExitStatus127) {
    const auto launcher = install("");
    const auto result = runProcess({launcher.string(), "--version"});
    EXPECT_EQ(result.exitCode, 127);
    EXPECT_EQ(result.out, "");
    EXPECT_NE(result.err.find("iblkit: the program is missing: no "), std::string::npos) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
}

} // namespace
} // namespace iblkit::testing
