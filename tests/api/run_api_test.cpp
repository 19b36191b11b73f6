// iblkit::executeRunFile as a program calls it: a documented run file passes with its report, a
// failed expectation is a result rather than an error, and a run file that cannot be read or whose
// shader does not compile is an iblkit::Error of its kind.
#include <iblkit/iblkit.hpp>

#include "read_file.hpp"
#include "temp_folder.hpp"
#include "thrown_error.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>

namespace iblkit {
namespace {

namespace fs = std::filesystem;

// PBR.fxh's functions at two arguments against the C++ float twin: a dispatch of two threads.
const fs::path kPbrExample = "docs/examples/pbr_functions.run.json";

// The example, its paths made absolute, written into `folder` with `edit` applied.
fs::path editedExample(const testing::TempFolder& folder, const std::function<void(nlohmann::json&)>& edit) {
    auto run = nlohmann::json::parse(testing::readFile(kPbrExample));
    run["shader"] = fs::absolute(kPbrExample.parent_path() / run["shader"].get<std::string>()).lexically_normal().string();
    run["include"] = nlohmann::json::array({fs::absolute("hlsl/document").string()});
    edit(run);
    return folder.write("edited.run.json", run.dump(2));
}

RunRequest requestFor(const fs::path& runFile) {
    RunRequest request;
    request.runFile = runFile;
    return request;
}

// The kind and message of the Error running `runFile` throws.
std::pair<ErrorKind, std::string> runErrorOf(const fs::path& runFile) {
    return testing::errorOf([&] { executeRunFile(requestFor(runFile)); });
}

TEST(RunApi, TheDocumentedExamplePassesAndReportsAsItGoes) {
    std::ostringstream shown;
    auto request = requestFor(kPbrExample);
    request.reportStream = &shown;
    const auto result = executeRunFile(request);
    EXPECT_TRUE(result.passed) << result.report;
    EXPECT_NE(result.report.find("PASS Results: 32 values"), std::string::npos) << result.report;
    EXPECT_NE(result.report.find("1 of 1 expectations passed\n"), std::string::npos) << result.report;
    EXPECT_EQ(shown.str(), result.report);
}

TEST(RunApi, AFailedExpectationIsAResultNotAnError) {
    testing::TempFolder scratch;
    const auto runFile = editedExample(scratch, [](nlohmann::json& run) {
        run["expect"][0]["values"][0] = 0.5; // D at (N·H 1, roughness 1) is 1/pi, 0.3183
    });
    const auto result = executeRunFile(requestFor(runFile));
    EXPECT_FALSE(result.passed);
    EXPECT_NE(result.report.find("FAIL Results"), std::string::npos) << result.report;
    EXPECT_NE(result.report.find("0 of 1 expectations passed\n"), std::string::npos) << result.report;
}

TEST(RunApi, ARunFileThatCannotBeReadIsBadInput) {
    testing::TempFolder scratch;
    const auto [kind, message] = runErrorOf(scratch.path() / "missing.run.json");
    EXPECT_EQ(kind, ErrorKind::BadInput);
    EXPECT_NE(message.find("missing.run.json"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;

    const auto unknownKey = editedExample(scratch, [](nlohmann::json& run) { run["dispatch_size"] = 1; });
    const auto [keyKind, keyMessage] = runErrorOf(unknownKey);
    EXPECT_EQ(keyKind, ErrorKind::BadInput);
    EXPECT_NE(keyMessage.find("dispatch_size"), std::string::npos) << keyMessage;
}

TEST(RunApi, AShaderThatDoesNotCompileIsCompileFailed) {
    testing::TempFolder scratch;
    const auto shader = scratch.write("broken.hlsl", "[numthreads(1, 1, 1)]\nvoid main() { undeclared = 1; }\n");
    const auto runFile = editedExample(scratch, [&](nlohmann::json& run) { run["shader"] = shader.string(); });
    const auto [kind, message] = runErrorOf(runFile);
    EXPECT_EQ(kind, ErrorKind::CompileFailed);
    EXPECT_NE(message.find("broken.hlsl:2:"), std::string::npos) << message;
}

} // namespace
} // namespace iblkit
