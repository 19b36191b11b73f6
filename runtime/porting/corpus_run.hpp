#pragma once

#include "corpus_manifest.hpp"
#include "compiler.hpp"
#include "cross_compile.hpp"
#include "run_executor.hpp"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace iblkit::porting {

// One form of a corpus shader: produced and read back by the compiler that reads it (glslang for
// GLSL and ESSL, the kit again for the HLSL round trip; MSL has no reader on Debian), or not,
// with the refusal or the reader's error.
struct FormOutcome {
    bool produced = false;
    std::string message; // the refusal, or the reader's error; "" for a form produced and read back
};

// Every form of a compiled shader, each produced and read back or refused.
std::map<compiler::CrossTarget, FormOutcome> formOutcomes(const compiler::CompiledShader& shader,
                                                          const compiler::CompileOptions& options);

// Passed and Failed: the run file's expectations on every path that ran. Seeded: no run file, run
// with seeded resources (run::seededRun), which only the paths' agreement judges. NotRun: no run
// file, and the shader cannot be run with seeded resources (ShaderOutcome::notRun says why).
enum class RunOutcome { NotRun, Passed, Failed, Seeded };

// What the compiler and the device made of one corpus shader.
struct ShaderOutcome {
    std::string name;
    std::string compileError; // empty when it compiled
    std::vector<std::string> warnings;
    std::vector<std::string> kitEdits;
    std::map<compiler::CrossTarget, FormOutcome> forms; // every form, when it compiled
    RunOutcome run = RunOutcome::NotRun;
    std::string runLog; // what the run printed, or why it could not be carried out
    std::string notRun; // why a shader without a run file was not run
    bool seeded = false; // run with seeded resources, having no run file
    // Each path of run::RunApi::All (Vulkan from the SPIR-V, from the HLSL form, OpenGL), and
    // whether those that ran wrote the same values.
    std::vector<run::PathOutcome> paths;
    bool pathsAgree = false;
};

// Compiles the shader into every form, reads each form back, and carries out its run file (or a
// seeded run) on every path.
ShaderOutcome runCorpusShader(const CorpusShader& shader, const run::RunOptions& runOptions);

enum class FeatureStatus { Supported, Lowered, Warned, Refused };
std::string_view statusName(FeatureStatus status); // "supported", "lowered by the kit", ...

// A feature judged on its shader's outcome: its status, and every way the outcome differs from
// what the manifest says of the feature (empty when it agrees).
struct FeatureOutcome {
    CorpusFeature feature;
    FeatureStatus status = FeatureStatus::Supported;
    std::vector<std::string> mismatches;
};
FeatureOutcome judgeFeature(const CorpusFeature& feature, const ShaderOutcome& shader);

struct CorpusResults {
    std::vector<ShaderOutcome> shaders;
    std::vector<FeatureOutcome> features;
    bool agrees() const; // every feature as the manifest says
    const ShaderOutcome& shaderNamed(const std::string& name) const;
};

// Every shader of the corpus, then every feature judged. `progress` gets a line per shader.
CorpusResults runCorpus(const CorpusManifest& manifest, const run::RunOptions& runOptions,
                        const std::function<void(const std::string&)>& progress = {});

} // namespace iblkit::porting
