// The bake folder is all or nothing: a bake lands whole or not at all, an earlier bake is
// replaced only by a finished one, and a folder that is not a bake is never replaced.
#include "bake_directory.hpp"
#include "bake_error.hpp"
#include "read_file.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

namespace iblkit::bake {
namespace {

namespace fs = std::filesystem;
using iblkit::testing::TempFolder;

size_t entriesIn(const fs::path& folder) {
    return std::distance(fs::directory_iterator(folder), fs::directory_iterator());
}

TEST(BakeDirectory, CommitMovesTheBakeIntoAnAbsentTarget) {
    TempFolder scratch;
    const auto target = scratch.path() / "nested" / "out";
    {
        BakeDirectory directory(target);
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
    scratch.write("out/manifest.json", R"({"generator": "iblkit"})");
    scratch.write("out/specular.ktx2", "old");
    {
        BakeDirectory directory(target);
        scratch.write(fs::relative(directory.staging() / "specular.ktx2", scratch.path()), "half-written");
    } // failed before commit
    EXPECT_EQ(iblkit::testing::readFile(target / "specular.ktx2"), "old");
    EXPECT_EQ(entriesIn(scratch.path()), 1u);
}

TEST(BakeDirectory, CommitReplacesAnEarlierBakeWhole) {
    TempFolder scratch;
    const auto target = scratch.path() / "out";
    scratch.write("out/manifest.json", R"({"generator": "iblkit"})");
    scratch.write("out/stale.dds", "from an earlier --dds bake");
    BakeDirectory directory(target);
    scratch.write(fs::relative(directory.staging() / "manifest.json", scratch.path()), R"({"generator": "iblkit", "new": 1})");
    directory.commit();
    EXPECT_FALSE(fs::exists(target / "stale.dds"));
    EXPECT_NE(iblkit::testing::readFile(target / "manifest.json").find("new"), std::string::npos);
    EXPECT_EQ(entriesIn(scratch.path()), 1u);
}

TEST(BakeDirectory, AFolderThatIsNotABakeIsRefusedAndKept) {
    TempFolder scratch;
    scratch.write("photos/holiday.jpg", "precious");
    EXPECT_THROW(BakeDirectory(scratch.path() / "photos"), BakeError);
    scratch.write("notes.txt", "a file");
    EXPECT_THROW(BakeDirectory(scratch.path() / "notes.txt"), BakeError);
    scratch.write("other/manifest.json", R"({"generator": "something else"})");
    EXPECT_THROW(BakeDirectory(scratch.path() / "other"), BakeError);
    EXPECT_EQ(iblkit::testing::readFile(scratch.path() / "photos/holiday.jpg"), "precious");
    EXPECT_EQ(entriesIn(scratch.path()), 3u) << "no staging folder is left behind";
}

TEST(BakeDirectory, AnEmptyFolderMayReceiveABake) {
    TempFolder scratch;
    fs::create_directories(scratch.path() / "empty");
    BakeDirectory directory(scratch.path() / "empty");
    scratch.write(fs::relative(directory.staging() / "manifest.json", scratch.path()), "{}");
    directory.commit();
    EXPECT_TRUE(fs::exists(scratch.path() / "empty" / "manifest.json"));
}

} // namespace
} // namespace iblkit::bake
