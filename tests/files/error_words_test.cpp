// nlohmann's and std::filesystem's exceptions in the kit's words: no "[json.exception...]" code
// or "filesystem error:" prefix reaches a user.
#include "error_words.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace iblkit::files {
namespace {

template <typename Read>
std::string wordsOf(Read read) {
    try {
        read();
    } catch (const nlohmann::json::exception& error) {
        return jsonErrorInWords(error);
    }
    return "(no error)";
}

TEST(JsonWords, ASyntaxErrorNamesItsLineAndColumn) {
    EXPECT_EQ(wordsOf([] { const auto ignored = nlohmann::json::parse("{\n  \"a\": ]"); }),
              "not valid JSON at line 2, column 8: syntax error while parsing value - unexpected ']'; expected '[', '{', "
              "or a literal");
}

TEST(JsonWords, AWrongTypeAMissingKeyAndAMissingElement) {
    const auto json = nlohmann::json::parse(R"({"size": "big", "list": [1]})");
    EXPECT_EQ(wordsOf([&] { (void)json.at("size").get<int>(); }), "expected a number, found a string");
    EXPECT_EQ(wordsOf([&] { (void)json.at("list").get<std::string>(); }), "expected a string, found an array");
    EXPECT_EQ(wordsOf([&] { (void)json.at("shaders"); }), "\"shaders\" is missing");
    EXPECT_EQ(wordsOf([&] { (void)json.at("list").at(3); }), "element 3 is missing");
}

TEST(JsonWords, NoMessageKeepsTheExceptionsCode) {
    const auto json = nlohmann::json::parse(R"({"a": 1})");
    const auto words = wordsOf([&] { (void)json.at("a").at("b"); });
    EXPECT_EQ(words.find("json.exception"), std::string::npos) << words;
    EXPECT_FALSE(words.empty());
}

TEST(FilesystemWords, TheOperationThePathsAndTheReason) {
    const std::filesystem::filesystem_error one("cannot create directories", "a/b",
                                                std::make_error_code(std::errc::not_a_directory));
    EXPECT_EQ(filesystemErrorInWords(one), "cannot create directories 'a/b': Not a directory");
    const std::filesystem::filesystem_error two("cannot rename", "x", "y", std::make_error_code(std::errc::permission_denied));
    EXPECT_EQ(filesystemErrorInWords(two), "cannot rename 'x' and 'y': Permission denied");
    const std::filesystem::filesystem_error none("temp_directory_path", std::make_error_code(std::errc::not_a_directory));
    EXPECT_EQ(filesystemErrorInWords(none), "temp_directory_path: Not a directory");
}

} // namespace
} // namespace iblkit::files
