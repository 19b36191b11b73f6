#pragma once
// The fixture of the `iblkit bake` command-line tests: the program run as a user runs it, small
// settings, and a failure check that the folder stayed as it was.
#include "read_file.hpp"
#include "run_process.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace iblkit::testing {

// Every file of a folder with its contents, to show a folder did not change.
inline std::map<std::string, std::string> snapshot(const std::filesystem::path& folder) {
    std::map<std::string, std::string> files;
    if (!std::filesystem::exists(folder)) return files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
        if (entry.is_regular_file()) files[std::filesystem::relative(entry.path(), folder).string()] = readFile(entry.path());
    return files;
}

// A Radiance HDR file of flat RGBE texels (stb reads widths below 8 and non-RLE rows as flat).
inline std::string radianceHdr(uint32_t width, uint32_t height, unsigned char exponent) {
    std::string text = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(height) + " +X " +
                       std::to_string(width) + "\n";
    for (uint32_t i = 0; i < width * height; ++i) text += std::string{char(128), char(128), char(128), char(exponent)};
    return text;
}

class BakeCli : public ::testing::Test {
protected:
    // Each test bakes with a cache of its own, outside the folder a failed bake must leave as it was.
    ProcessResult iblkit(std::vector<std::string> arguments, double killAfterSeconds = 0, int killSignal = 9) const {
        arguments.insert(arguments.begin(), IBLKIT_EXECUTABLE);
        return runProcess(arguments, {"XDG_CACHE_HOME=" + cache.path().string()}, killAfterSeconds, killSignal);
    }
    // Small and quick: what every test but the default bake runs with.
    std::vector<std::string> small(std::vector<std::string> arguments) const {
        for (const char* flag : {"--size", "16", "--samples", "16", "--lut-size", "8", "--lut-samples", "16",
                                 "--irradiance-size", "4", "--quiet"})
            arguments.push_back(flag);
        return arguments;
    }
    void expectFailure(const std::vector<std::string>& arguments, const std::string& expected) const {
        const auto before = snapshot(scratch.path());
        const auto result = iblkit(arguments);
        EXPECT_NE(result.exitCode, 0);
        EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_EQ(snapshot(scratch.path()), before) << "a failed bake changed the folder";
    }
    std::string at(const std::string& name) const { return (scratch.path() / name).string(); }

    TempFolder scratch;
    TempFolder cache{"-cache"};
};

} // namespace iblkit::testing
