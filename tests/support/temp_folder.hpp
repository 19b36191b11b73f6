#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace iblkit::testing {

// A fresh folder per test for HLSL snippets, removed afterwards.
class TempFolder {
public:
    // `suffix` tells apart two folders of one test.
    explicit TempFolder(const std::string& suffix = "") {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = "iblkit-" + std::to_string(::getpid()) + "-" + test->test_suite_name() + "-" + test->name() + suffix;
        std::replace(name.begin(), name.end(), '/', '_'); // parameterized tests' names hold slashes
        path_ = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempFolder() { std::filesystem::remove_all(path_); }
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;

    std::filesystem::path write(const std::string& name, const std::string& text) const {
        const auto file = path_ / name;
        std::filesystem::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

} // namespace iblkit::testing
