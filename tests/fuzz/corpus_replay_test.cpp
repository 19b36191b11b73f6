// Every input of tests/fuzz/corpus (the seeds and every crash a fuzzer ever found) through its
// target: each must end in a result or its documented error, and never escape another way.
#include "fuzz_targets.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace iblkit::fuzz {
namespace {

namespace fs = std::filesystem;

std::vector<std::byte> bytesOf(const fs::path& path) {
    std::ifstream stream(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
    const auto* data = reinterpret_cast<const std::byte*>(text.data());
    return {data, data + text.size()};
}

class CorpusReplay : public ::testing::TestWithParam<Target> {};

TEST_P(CorpusReplay, EveryInputEndsInAResultOrItsError) {
    const auto folder = fs::path("tests/fuzz/corpus") / GetParam().name;
    ASSERT_TRUE(fs::is_directory(folder)) << folder << " is missing";
    size_t inputs = 0;
    for (const auto& entry : fs::directory_iterator(folder)) {
        const auto bytes = bytesOf(entry.path());
        EXPECT_NO_THROW(GetParam().run(bytes)) << entry.path();
        ++inputs;
    }
    EXPECT_GT(inputs, 0u) << "no seed for " << GetParam().name;
}

INSTANTIATE_TEST_SUITE_P(Targets, CorpusReplay, ::testing::ValuesIn(targets()),
                         [](const auto& info) { return std::string(info.param.name); });

} // namespace
} // namespace iblkit::fuzz
