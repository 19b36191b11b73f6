// A batch list: words split as a shell splits them, comments and blank lines skipped, and every
// bad line refused with its file and line number.
#include "batch_error.hpp"
#include "batch_list.hpp"

#include <gtest/gtest.h>

namespace iblkit::batch {
namespace {

std::string errorOf(std::string_view text) {
    try {
        parseBatchList(text, "list.txt");
    } catch (const BatchError& error) {
        return error.what();
    }
    return "no error";
}

TEST(BatchList, WordsAreSplitAsAShellSplitsThem) {
    EXPECT_EQ(splitWords("a 'b c' \"d e\" f\\ g h#i # comment"),
              (std::vector<std::string>{"a", "b c", "d e", "f g", "h#i"}));
    EXPECT_EQ(splitWords("  \t "), std::vector<std::string>{});
    EXPECT_EQ(splitWords("''"), std::vector<std::string>{""});
    EXPECT_THROW(splitWords("a 'b"), std::invalid_argument);
    EXPECT_THROW(splitWords("a\\"), std::invalid_argument);
}

TEST(BatchList, EachBadLineIsRefusedWithItsNumber) {
    EXPECT_EQ(errorOf("a\n../up x.exr\n"), "list.txt:2: error: '../up' is not a folder name (letters, digits, '.', '_' "
                                           "and '-', not starting with '.')");
    EXPECT_EQ(errorOf("a\n# b\na --size 16\n"), "list.txt:3: error: 'a' is named on line 1 already");
    EXPECT_EQ(errorOf("a 'open\n"), "list.txt:1: error: the quote ' is not closed");
    EXPECT_EQ(errorOf("batch.json\n"), "list.txt:1: error: 'batch.json' is the batch's own record's name");
    EXPECT_EQ(errorOf("# nothing\n\n"), "list.txt: error: the list names no bake");
}

TEST(BatchList, LinesKeepTheirNumbersAndWords) {
    const auto lines = parseBatchList("# header\nforest /data/forest.exr --size 512\r\n\nsky --profile babylon", "l");
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0].number, 2u);
    EXPECT_EQ(lines[0].name, "forest");
    EXPECT_EQ(lines[0].arguments, (std::vector<std::string>{"/data/forest.exr", "--size", "512"}));
    EXPECT_EQ(lines[1].number, 4u);
    EXPECT_EQ(lines[1].arguments, (std::vector<std::string>{"--profile", "babylon"}));
}

TEST(BatchList, FolderNames) {
    for (const char* good : {"a", "forest-three", "probe_001.v2", "A9"}) EXPECT_TRUE(isFolderName(good)) << good;
    for (const char* bad : {"", ".", "..", ".hidden", "a/b", "a b", "ü"}) EXPECT_FALSE(isFolderName(bad)) << bad;
}

} // namespace
} // namespace iblkit::batch
