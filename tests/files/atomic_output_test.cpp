#include "atomic_output.hpp"
#include "read_file.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using iblkit::files::AtomicOutput;
using iblkit::files::FileError;

namespace {

class AtomicOutputTest : public ::testing::Test {
protected:

    size_t entriesInFolder() const { return std::distance(fs::directory_iterator(folder), fs::directory_iterator()); }

    iblkit::testing::TempFolder scratch;
    const fs::path& folder = scratch.path();
};

TEST_F(AtomicOutputTest, CommitWritesEveryFile) {
    AtomicOutput output;
    output.add(folder / "a.txt", "alpha");
    output.add(folder / "b.txt", "beta");
    output.commit();
    EXPECT_EQ(iblkit::testing::readFile(folder / "a.txt"), "alpha");
    EXPECT_EQ(iblkit::testing::readFile(folder / "b.txt"), "beta");
    EXPECT_EQ(entriesInFolder(), 2u) << "no temporary may be left behind";
}

TEST_F(AtomicOutputTest, NothingIsWrittenWithoutCommit) {
    {
        AtomicOutput output;
        output.add(folder / "a.txt", "alpha");
    }
    EXPECT_EQ(entriesInFolder(), 0u);
}

TEST_F(AtomicOutputTest, AFailedAddKeepsExistingFilesAndLeavesNoTemporaries) {
    {
        std::ofstream(folder / "good.spv") << "GOOD";
    }
    AtomicOutput output;
    output.add(folder / "good.spv", "NEW");
    EXPECT_THROW(output.add(folder / "missing" / "x.txt", "x"), FileError);
    EXPECT_EQ(iblkit::testing::readFile(folder / "good.spv"), "GOOD");
    EXPECT_EQ(entriesInFolder(), 1u);
}

// A 250-byte name is valid; its temporary was the name plus 12 bytes, past the 255-byte limit.
TEST_F(AtomicOutputTest, AnOutputNamedNearTheFileSystemsLimitIsWritten) {
    const auto path = folder / (std::string(250, 'n') + ".spv");
    AtomicOutput output;
    output.add(path, "bytes");
    output.commit();
    EXPECT_EQ(iblkit::testing::readFile(path), "bytes");
    EXPECT_EQ(entriesInFolder(), 1u);
}

TEST_F(AtomicOutputTest, RefusesADirectoryAsOutput) {
    fs::create_directories(folder / "dir");
    AtomicOutput output;
    try {
        output.add(folder / "dir", "x");
        FAIL() << "expected FileError";
    } catch (const FileError& error) {
        EXPECT_NE(std::string(error.what()).find("is a directory"), std::string::npos) << error.what();
    }
}

// stress and consistency read the kernels' HLSL from hlsl/, porting its corpus: an output that
// is one of those files is refused; a new file beside them is not an input.
TEST(RequireNotAnInputIn, AnExistingFileOfTheFolderIsAnInput) {
    iblkit::testing::TempFolder folder;
    const auto manifest = folder.write("hlsl/shaders.json", "{}");
    folder.write("hlsl/Common/PBR.fxh", "// pbr");
    using iblkit::files::requireNotAnInputIn;
    EXPECT_THROW(requireNotAnInputIn(manifest, folder.path() / "hlsl"), FileError);
    EXPECT_THROW(requireNotAnInputIn(folder.path() / "hlsl" / "Common" / ".." / "Common" / "PBR.fxh", folder.path() / "hlsl"),
                 FileError);
    EXPECT_NO_THROW(requireNotAnInputIn(folder.path() / "hlsl" / "report.md", folder.path() / "hlsl"));
    EXPECT_NO_THROW(requireNotAnInputIn(folder.write("elsewhere.md", "x"), folder.path() / "hlsl"));
    EXPECT_NO_THROW(requireNotAnInputIn(manifest, folder.path() / "no-such-folder"));
}

} // namespace
