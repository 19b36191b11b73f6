// Bad input gives a precise "file:line:column: error:" message, with the include chain.
#include "compile_error.hpp"
#include "compiler.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

namespace iblkit::compiler {
namespace {

class CompileErrors : public ::testing::Test {
protected:
    std::string errorOf(const std::filesystem::path& source, const std::string& entry = "main") {
        CompileOptions options;
        options.source = source;
        options.entryPoint = entry;
        options.includeDirs.push_back(folder.path() / "include");
        try {
            compileShader(options);
        } catch (const CompileError& error) {
            return error.what();
        }
        ADD_FAILURE() << "compiled without an error";
        return "";
    }
    testing::TempFolder folder;
};

constexpr const char* kValidBody = "[numthreads(1, 1, 1)]\nvoid main(uint3 id : SV_DispatchThreadID) {}\n";

TEST_F(CompileErrors, SyntaxErrorNamesFileLineAndColumn) {
    const auto source = folder.write("syntax.hlsl", "[numthreads(1, 1, 1)]\nvoid main()\n{\n    float x = undefinedThing;\n}\n");
    const auto message = errorOf(source);
    EXPECT_EQ(message, source.string() + ":4:15: error: 'undefinedThing' : unknown variable") << message;
}

TEST_F(CompileErrors, ErrorInAnIncludeShowsTheIncludeChain) {
    folder.write("include/Common/Bad.fxh", "float broken()\n{\n    return nothere;\n}\n");
    folder.write("include/Outer.fxh", "#include \"Common/Bad.fxh\"\n");
    const auto source = folder.write("main.hlsl", std::string("// top\n#include \"Outer.fxh\"\n") + kValidBody);
    const auto message = errorOf(source);
    const auto outer = (folder.path() / "include/Outer.fxh").string();
    const auto bad = (folder.path() / "include/Common/Bad.fxh").string();
    EXPECT_EQ(message, "In file included from " + source.string() + ":2:\nIn file included from " + outer + ":1:\n" +
                           bad + ":3:12: error: 'nothere' : unknown variable")
        << message;
}

TEST_F(CompileErrors, MissingIncludeNamesTheDirectiveAndHeader) {
    const auto source = folder.write("missing.hlsl", std::string("#include \"Nowhere.fxh\"\n") + kValidBody);
    const auto message = errorOf(source);
    EXPECT_EQ(message.rfind(source.string() + ":1:", 0), 0u) << message;
    EXPECT_NE(message.find("Nowhere.fxh"), std::string::npos) << message;
}

TEST_F(CompileErrors, UnknownEntryPoint) {
    const auto source = folder.write("entry.hlsl", kValidBody);
    EXPECT_EQ(errorOf(source, "CSMain"), source.string() + ": error: entry point 'CSMain' is not defined");
}

TEST_F(CompileErrors, MissingSourceFile) {
    const auto source = folder.path() / "absent.hlsl";
    EXPECT_EQ(errorOf(source), source.string() + ": error: no such file");
}

TEST_F(CompileErrors, TwoResourcesInOneRegister) {
    const auto source = folder.write("clash.hlsl", R"(
RWTexture2D<float4> A : register(u1);
RWTexture2D<float4> B : register(u1);
[numthreads(1, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) { A[id.xy] = 1; B[id.xy] = 2; }
)");
    EXPECT_EQ(errorOf(source), source.string() + ": error: register u1, space0 is used by both 'A' and 'B'");
}

} // namespace
} // namespace iblkit::compiler
