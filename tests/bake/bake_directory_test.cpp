// The bake folder is all or nothing: a bake lands whole or not at all, an earlier bake is
// replaced only by a finished one, and only when it holds nothing but the files it wrote; a
// folder that holds anything else, the input, or that cannot be replaced is refused up front.
#include "bake_directory.hpp"
#include "bake_outputs.hpp"
#include "bake_error.hpp"
#include "read_file.hpp"
#include "sha256.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace iblkit::bake {
namespace {

namespace fs = std::filesystem;
using iblkit::testing::TempFolder;

size_t entriesIn(const fs::path& folder) {
    return std::distance(fs::directory_iterator(folder), fs::directory_iterator());
}

// An earlier bake as iblkit writes one: its files, and a manifest listing each with its hash.
void writeEarlierBake(const TempFolder& scratch, const std::string& folder,
                      const std::vector<std::pair<std::string, std::string>>& files) {
    std::string list;
    for (const auto& [name, contents] : files) {
        const auto path = scratch.write(folder + "/" + name, contents);
        list += std::string(list.empty() ? "" : ", ") + R"({"name": ")" + name + R"(", "sha256": ")" + cache::sha256OfFile(path) + "\"}";
    }
    scratch.write(folder + "/manifest.json", R"({"generator": "iblkit", "files": [)" + list + "]}");
}

std::string messageOf(const fs::path& target, const std::optional<fs::path>& input = std::nullopt) {
    try {
        BakeDirectory directory(target, input);
    } catch (const BakeError& error) {
        return error.what();
    }
    return "no error";
}

// A file the disk cannot take (/dev/full: every write is ENOSPC, first seen when the bytes are
// flushed) is an error that says why.
TEST(BakeOutputs, AFullDiskIsAnErrorWithItsReason) {
    const std::string bytes(1 << 16, 'x');
    try {
        writeBytes("/dev", "full", std::as_bytes(std::span(bytes)));
        ADD_FAILURE() << "no error";
    } catch (const BakeError& error) {
        EXPECT_EQ(std::string(error.what()), "cannot write '/dev/full': No space left on device");
    }
}

// A bake killed outright leaves its staging folder; the next bake beside it removes it once its
// process is gone, and never a live bake's.
TEST(BakeDirectory, AKilledBakesStagingFolderIsRemovedByTheNextBake) {
    iblkit::testing::TempFolder folder;
    char host[256] = {};
    gethostname(host, sizeof host - 1);
    const pid_t child = fork(); // a process id that is surely gone once reaped
    if (child == 0) _exit(0);
    waitpid(child, nullptr, 0);
    const auto staging = [&](pid_t pid) {
        const auto path = folder.path() / (".iblkit-partial-" + std::string(host) + "-" + std::to_string(pid) + "-aB3xYz");
        fs::create_directories(path);
        std::ofstream(path / "specular.ktx2") << "half a file";
        return path;
    };
    const auto killed = staging(child), live = staging(getpid());
    BakeDirectory directory(folder.path() / "out", std::nullopt);
    EXPECT_FALSE(fs::exists(killed));
    EXPECT_TRUE(fs::exists(live));
    EXPECT_TRUE(fs::exists(directory.staging()));
}

TEST(BakeDirectory, CommitMovesTheBakeIntoAnAbsentTarget) {
    TempFolder scratch;
    const auto target = scratch.path() / "nested" / "out";
    {
        BakeDirectory directory(target, std::nullopt);
        scratch.write(fs::relative(directory.staging() / "a.txt", scratch.path()), "new");
        EXPECT_FALSE(fs::exists(target));
        directory.commit();
    }
    EXPECT_EQ(iblkit::testing::readFile(target / "a.txt"), "new");
    EXPECT_EQ(entriesIn(target.parent_path()), 1u) << "no staging folder is left behind";
}

TEST(BakeDirectory, AnUncommittedBakeLeavesTheEarlierOneAsItWas) {
    TempFolder scratch;
    const auto target = scratch.path() / "out";
    writeEarlierBake(scratch, "out", {{"specular.ktx2", "old"}});
    {
        BakeDirectory directory(target, std::nullopt);
        scratch.write(fs::relative(directory.staging() / "specular.ktx2", scratch.path()), "half-written");
    } // failed before commit
    EXPECT_EQ(iblkit::testing::readFile(target / "specular.ktx2"), "old");
    EXPECT_EQ(entriesIn(scratch.path()), 1u);
}

TEST(BakeDirectory, CommitReplacesAnEarlierBakeWhole) {
    TempFolder scratch;
    const auto target = scratch.path() / "out";
    writeEarlierBake(scratch, "out", {{"stale.dds", "from an earlier --dds bake"}, {"exr/specular_mip0.exr", "exr"}});
    BakeDirectory directory(target, std::nullopt);
    scratch.write(fs::relative(directory.staging() / "manifest.json", scratch.path()), R"({"generator": "iblkit", "new": 1})");
    directory.commit();
    EXPECT_FALSE(fs::exists(target / "stale.dds"));
    EXPECT_NE(iblkit::testing::readFile(target / "manifest.json").find("new"), std::string::npos);
    EXPECT_EQ(entriesIn(scratch.path()), 1u);
}

// The check before the commit takes a file the first check found whole, and whose status has not
// changed since, without hashing it again; a file written in between is hashed, and refused.
TEST(BakeDirectory, AFileEditedDuringTheBakeIsFoundAtTheCommit) {
    TempFolder scratch;
    writeEarlierBake(scratch, "kept", {{"specular.ktx2", "bake"}});
    writeEarlierBake(scratch, "edited", {{"specular.ktx2", "bake"}});
    // Files changed within the last second are always hashed again: these must be older.
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    BakeDirectory kept(scratch.path() / "kept", std::nullopt);
    scratch.write(fs::relative(kept.staging() / "manifest.json", scratch.path()), R"({"generator": "iblkit", "new": 1})");
    EXPECT_NO_THROW(kept.commit());
    BakeDirectory edited(scratch.path() / "edited", std::nullopt);
    scratch.write("edited/specular.ktx2", "edited by hand during the bake");
    try {
        edited.commit();
        ADD_FAILURE() << "a file edited during the bake was replaced";
    } catch (const BakeError& error) {
        EXPECT_NE(std::string(error.what()).find("'specular.ktx2' changed since the earlier bake wrote it"), std::string::npos);
    }
    EXPECT_EQ(iblkit::testing::readFile(scratch.path() / "edited/specular.ktx2"), "edited by hand during the bake");
}

// A bake begun again in the same staging folder (baked_outputs.cpp's device check) leaves none
// of the first attempt's files.
TEST(BakeDirectory, ClearingTheStagingFolderLeavesNothingOfTheFirstAttempt) {
    TempFolder scratch;
    BakeDirectory directory(scratch.path() / "out", std::nullopt);
    scratch.write(fs::relative(directory.staging() / "lights.gltf", scratch.path()), "first attempt");
    scratch.write(fs::relative(directory.staging() / "exr/x.exr", scratch.path()), "first attempt");
    directory.clearStaging();
    EXPECT_TRUE(fs::is_directory(directory.staging()));
    EXPECT_EQ(entriesIn(directory.staging()), 0u);
}

TEST(BakeDirectory, AFolderThatIsNotABakeIsRefusedAndKept) {
    TempFolder scratch;
    scratch.write("photos/holiday.jpg", "precious");
    EXPECT_THROW(BakeDirectory(scratch.path() / "photos", std::nullopt), BakeError);
    scratch.write("notes.txt", "a file");
    EXPECT_THROW(BakeDirectory(scratch.path() / "notes.txt", std::nullopt), BakeError);
    scratch.write("other/manifest.json", R"({"generator": "something else"})");
    EXPECT_THROW(BakeDirectory(scratch.path() / "other", std::nullopt), BakeError);
    EXPECT_EQ(iblkit::testing::readFile(scratch.path() / "photos/holiday.jpg"), "precious");
    EXPECT_EQ(entriesIn(scratch.path()), 3u) << "no staging folder is left behind";
}

// A manifest that merely said {"generator": "iblkit"} had every file of its folder deleted, and
// so did a bake with a user's NOTES.txt or custom/ beside its own files.
TEST(BakeDirectory, OnlyTheFilesAnEarlierBakeListedWithTheirHashesAreReplaced) {
    TempFolder scratch;
    scratch.write("bare/manifest.json", R"({"generator": "iblkit"})");
    scratch.write("bare/mine.txt", "a user's");
    EXPECT_NE(messageOf(scratch.path() / "bare").find("no manifest.json written by iblkit"), std::string::npos);
    writeEarlierBake(scratch, "notes", {{"specular.ktx2", "bake"}});
    scratch.write("notes/NOTES.txt", "a user's");
    EXPECT_NE(messageOf(scratch.path() / "notes").find("it holds 'NOTES.txt', which no earlier bake wrote"), std::string::npos);
    writeEarlierBake(scratch, "custom", {{"specular.ktx2", "bake"}});
    scratch.write("custom/custom/x.bin", "a user's");
    EXPECT_NE(messageOf(scratch.path() / "custom").find("'custom/x.bin', which no earlier bake wrote"), std::string::npos);
    writeEarlierBake(scratch, "edited", {{"specular.ktx2", "bake"}});
    scratch.write("edited/specular.ktx2", "edited by hand");
    EXPECT_NE(messageOf(scratch.path() / "edited").find("'specular.ktx2' changed since the earlier bake wrote it"),
              std::string::npos);
    EXPECT_EQ(iblkit::testing::readFile(scratch.path() / "notes/NOTES.txt"), "a user's");
}

// `bake p/env.exr -o p` deleted the input, and the manifest then named a file that was gone.
TEST(BakeDirectory, AnOutputFolderThatHoldsTheInputIsRefused) {
    TempFolder scratch;
    const auto input = scratch.write("p/env.exr", "radiance");
    EXPECT_NE(messageOf(scratch.path() / "p", input).find("overlap: the bake would delete its own input"), std::string::npos);
    writeEarlierBake(scratch, "q", {{"specular.ktx2", "bake"}});
    EXPECT_NE(messageOf(scratch.path() / "q", scratch.path() / "q" / "specular.ktx2").find("overlap"), std::string::npos);
    EXPECT_NE(messageOf(scratch.path() / "faces" / "out", scratch.path() / "faces").find("overlap"), std::string::npos);
    EXPECT_TRUE(fs::exists(input));
}

// A link given as the target had the link replaced by a folder while its target kept the stale
// bake: the bake now lands in the folder the link names, and the link stays.
TEST(BakeDirectory, ALinkedTargetIsFollowed) {
    TempFolder scratch;
    writeEarlierBake(scratch, "real", {{"specular.ktx2", "old"}});
    fs::create_directory_symlink(scratch.path() / "real", scratch.path() / "link");
    BakeDirectory directory(scratch.path() / "link", std::nullopt);
    scratch.write(fs::relative(directory.staging() / "specular.ktx2", scratch.path()), "new");
    directory.commit();
    EXPECT_TRUE(fs::is_symlink(scratch.path() / "link"));
    EXPECT_EQ(iblkit::testing::readFile(scratch.path() / "real" / "specular.ktx2"), "new");
    fs::create_directory_symlink(scratch.path() / "nowhere", scratch.path() / "dangling");
    EXPECT_NE(messageOf(scratch.path() / "dangling").find("which does not exist"), std::string::npos);
}

// A read-only earlier bake was left behind under a .iblkit-partial name, with exit 0. Root writes
// into read-only folders, so as root the check runs in a child that has become user nobody.
bool readOnlyBakeIsRefused() {
    const auto folder = fs::temp_directory_path() / ("iblkit-read-only-" + std::to_string(::getpid()));
    fs::create_directories(folder / "out");
    const auto bake = folder / "out" / "specular.ktx2";
    { std::ofstream(bake) << "old"; }
    { std::ofstream(folder / "out" / "manifest.json") << R"({"generator": "iblkit", "files": [{"name": "specular.ktx2", "sha256": ")"
                                                      << cache::sha256OfFile(bake) << "\"}]}"; }
    fs::permissions(folder / "out", fs::perms::owner_write, fs::perm_options::remove);
    const bool refused = messageOf(folder / "out").find("is not writable") != std::string::npos;
    const bool untouched = entriesIn(folder) == 1;
    fs::permissions(folder / "out", fs::perms::owner_write, fs::perm_options::add);
    fs::remove_all(folder);
    return refused && untouched;
}

TEST(BakeDirectory, AnEarlierBakeThatCannotBeReplacedIsRefusedBeforeAnyWork) {
    if (::geteuid() != 0) {
        EXPECT_TRUE(readOnlyBakeIsRefused());
        return;
    }
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        constexpr uid_t kNobody = 65534;
        if (::setgid(kNobody) != 0 || ::setuid(kNobody) != 0) ::_exit(2);
        ::_exit(readOnlyBakeIsRefused() ? 0 : 1);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "1: not refused; 2: could not become nobody";
}

// mkdtemp makes a folder 0700; the bake's follows the umask.
TEST(BakeDirectory, TheBakeFolderFollowsTheUmask) {
    TempFolder scratch;
    const mode_t previous = ::umask(022);
    {
        BakeDirectory directory(scratch.path() / "out", std::nullopt);
        directory.commit();
    }
    ::umask(previous);
    EXPECT_EQ(fs::status(scratch.path() / "out").permissions() & fs::perms::all,
              fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                  fs::perms::others_exec);
}

// `-o .` inside a bake staged inside the target itself and failed only after all the work.
TEST(BakeDirectory, TheCurrentFolderAsTargetStagesBesideIt) {
    TempFolder scratch;
    writeEarlierBake(scratch, "out", {{"specular.ktx2", "old"}});
    const auto previous = fs::current_path();
    fs::current_path(scratch.path() / "out");
    {
        BakeDirectory directory(".", std::nullopt);
        EXPECT_EQ(directory.staging().parent_path(), scratch.path());
        scratch.write(fs::relative(directory.staging() / "specular.ktx2", scratch.path()), "new");
        directory.commit();
    }
    fs::current_path(previous);
    EXPECT_EQ(iblkit::testing::readFile(scratch.path() / "out" / "specular.ktx2"), "new");
}

// A 250-byte name is valid; the staging folder's name was the target's plus 23 bytes, past 255.
TEST(BakeDirectory, ATargetNamedNearTheFileSystemsLimitGetsAStagingFolder) {
    TempFolder scratch;
    const auto target = scratch.path() / std::string(250, 'n');
    BakeDirectory directory(target, std::nullopt);
    scratch.write(fs::relative(directory.staging() / "manifest.json", scratch.path()), "{}");
    directory.commit();
    EXPECT_TRUE(fs::exists(target / "manifest.json"));
}

TEST(BakeDirectory, AnEmptyFolderMayReceiveABake) {
    TempFolder scratch;
    fs::create_directories(scratch.path() / "empty");
    BakeDirectory directory(scratch.path() / "empty", std::nullopt);
    scratch.write(fs::relative(directory.staging() / "manifest.json", scratch.path()), "{}");
    directory.commit();
    EXPECT_TRUE(fs::exists(scratch.path() / "empty" / "manifest.json"));
}

} // namespace
} // namespace iblkit::bake
