// The installed headers (include/iblkit/) include the standard library and each other, nothing
// else: a program that uses the library needs none of the kit's dependencies to compile.
#include "read_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>

namespace iblkit {
namespace {

namespace fs = std::filesystem;

const std::set<std::string> kStandardHeaders = {"array",    "chrono", "cstddef", "cstdint", "filesystem",
                                                "functional", "map",  "optional", "ostream", "set",
                                                "stdexcept", "string", "string_view", "vector"};

TEST(PublicHeaders, IncludeOnlyTheStandardLibraryAndEachOther) {
    const std::regex include(R"(#\s*include\s*([<"])([^>"]+)[>"])");
    size_t headers = 0;
    for (const auto& entry : fs::directory_iterator("include/iblkit")) {
        ++headers;
        const auto text = testing::readFile(entry.path());
        for (auto it = std::sregex_iterator(text.begin(), text.end(), include); it != std::sregex_iterator(); ++it) {
            const std::string name = (*it)[2];
            const bool ownHeader = (*it)[1] == "<" && name.rfind("iblkit/", 0) == 0 && fs::exists("include" / fs::path(name));
            EXPECT_TRUE(ownHeader || ((*it)[1] == "<" && kStandardHeaders.count(name)))
                << entry.path() << " includes " << (*it)[0];
        }
    }
    EXPECT_EQ(headers, 7u);
}

} // namespace
} // namespace iblkit
