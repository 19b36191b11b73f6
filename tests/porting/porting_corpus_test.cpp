// hlsl/porting/ holds a shader for each porting feature (HLSL 2021 syntax, Vulkan attributes,
// wave operations, typed UAVs, groupshared memory, atomics). Each one compiles to SPIR-V (which
// the compiler validates) and to every form it can have: the GLSL and ESSL forms compile back
// through glslang, the Vulkan-semantics forms too, the HLSL round trip compiles again, and a
// form is refused only where the list below says so. Each run file passes on lavapipe with the
// validation layer on.
#include "compile_error.hpp"
#include "compiler.hpp"
#include "glsl_frontend.hpp"
#include "glslang_round_trip.hpp"
#include "run_process.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

namespace iblkit::compiler {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = "hlsl/porting";

const std::set<CrossTarget> kEveryForm = {CrossTarget::Glsl, CrossTarget::Essl,       CrossTarget::Msl,
                                          CrossTarget::Hlsl, CrossTarget::VulkanGlsl, CrossTarget::VulkanEssl};

// The forms that cannot express a corpus shader, and why.
const std::map<std::string, std::set<CrossTarget>> kRefused = {
    {"WavePrefix", {CrossTarget::Glsl, CrossTarget::Essl}}, // wave operations need Vulkan semantics
};

std::vector<std::string> corpusShaders() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(kCorpus))
        if (entry.path().extension() == ".hlsl") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

class PortingCorpus : public ::testing::TestWithParam<std::string> {
protected:
    CompiledShader compile() const {
        CompileOptions options;
        options.source = kCorpus / (GetParam() + ".hlsl");
        return compileShader(options);
    }
};

TEST_P(PortingCorpus, EveryFormIsProducedAndReadBackOrRefusedAsListed) {
    const auto shader = compile();
    const auto forms = crossCompileForms(shader, kEveryForm);
    const auto refused = kRefused.count(GetParam()) ? kRefused.at(GetParam()) : std::set<CrossTarget>{};
    for (const auto target : kEveryForm)
        EXPECT_EQ(forms.refused.count(target), refused.count(target))
            << crossTargetName(target) << ": " << (forms.refused.count(target) ? forms.refused.at(target) : "produced");
    for (const auto& [target, form] : forms.produced) {
        SCOPED_TRACE(std::string(crossTargetName(target)));
        if (target == CrossTarget::Glsl || target == CrossTarget::Essl) {
            EXPECT_EQ(testing::compileGlslBack(form.source), "") << form.source;
        }
        if (target == CrossTarget::VulkanGlsl || target == CrossTarget::VulkanEssl) {
            EXPECT_NO_THROW(compileVulkanGlsl(form.source, shader.reflection.stage, GetParam())) << form.source;
        }
        if (target == CrossTarget::Hlsl) {
            testing::TempFolder folder;
            CompileOptions again;
            again.source = folder.write("round_trip.hlsl", form.source);
            again.entryPoint = shader.reflection.entryPoint;
            EXPECT_NO_THROW(compileShader(again)) << form.source;
        }
    }
}

TEST_P(PortingCorpus, ItsRunFilePassesOnLavapipeWithValidation) {
    const auto runFile = kCorpus / (GetParam() + ".run.json");
    ASSERT_TRUE(fs::exists(runFile)) << "every corpus shader is a compute shader with a run file";
    const auto result = testing::runProcess({IBLKIT_EXECUTABLE, "run", runFile.string(), "--validate"});
    EXPECT_EQ(result.exitCode, 0) << result.out << result.err;
}

INSTANTIATE_TEST_SUITE_P(Shaders, PortingCorpus, ::testing::ValuesIn(corpusShaders()),
                         [](const auto& info) { return info.param; });

} // namespace
} // namespace iblkit::compiler
