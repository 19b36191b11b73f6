// docs/api.md shows the example program that tests/api builds and runs (ApiExample.RunsAsDocumented):
// the page's code is that file, so that what the page shows compiles against the headers and runs.
#include "read_file.hpp"

#include <gtest/gtest.h>

namespace iblkit {
namespace {

TEST(ApiDocs, ThePagesExampleIsTheProgramTheTestsRun) {
    const auto page = testing::readFile("docs/api.md");
    const auto program = testing::readFile("tests/api/example_program.cpp");
    ASSERT_FALSE(program.empty());
    EXPECT_NE(page.find("```cpp\n" + program + "```\n"), std::string::npos)
        << "copy tests/api/example_program.cpp into docs/api.md's example";
}

} // namespace
} // namespace iblkit
