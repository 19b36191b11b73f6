#pragma once

#include "codebase_manifest.hpp"
#include "corpus_run.hpp"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace iblkit::porting {

// What the kit made of one configuration of a code base: SPIR-V or the refusal, and each form.
struct ConfigurationOutcome {
    std::string label;
    std::string stage;  // profileStageName
    std::string target; // buildTargetName
    std::string profile;
    bool refusedStage = false; // ray tracing, mesh, amplification: counted apart
    std::string error;         // the refusal, every line of it; empty when it reached SPIR-V
    std::vector<std::string> kitEdits;
    std::vector<std::string> warnings;
    std::map<compiler::CrossTarget, FormOutcome> forms;
    // The shader run with seeded resources on every path of run::RunApi::All (Vulkan from the
    // SPIR-V, from the HLSL form, OpenGL from the GLSL form): which ran, whether they agree, why
    // it or a path did not run, and the first comparison that failed.
    std::vector<run::PathOutcome> paths;
    bool pathsAgree = false;
    std::string notRun;
    std::string disagreement;
    double seconds = 0;

    bool reachedSpirv() const { return error.empty(); }
    // Every form produced and read back, or refused by name because its language cannot express
    // the shader (wave operations in OpenGL GLSL, doubles in ESSL): nothing written that its own
    // compiler cannot read.
    bool everyForm() const;
    // Every form produced and read back.
    bool allSixForms() const;
    // Run on Vulkan, and every other path that could take it wrote the same numbers.
    bool sameNumbersWhereRun() const;
    // Run on all three paths, which wrote the same numbers.
    bool sameNumbersOnEveryPath() const;
};

// A configuration's failure, grouped: the kit's words with places, names and numbers taken out
// ("'X' is not supported: ..."), or for a shader that compiled, the first form that did not read
// back. Empty for a configuration with every form.
std::string failureCause(const ConfigurationOutcome& outcome);

// What a configuration may spend: a shader that hangs the frontend or explodes in memory costs
// that shader, not the run.
struct ConfigurationLimits {
    unsigned cpuSeconds = 60;
    unsigned wallSeconds = 120;
    size_t extraMegabytes = 3072;
};

// Compiles the configuration, makes every form and reads each back, in a child process under
// `limits`; then, in another, runs it with seeded resources on every path (run::seededRun).
ConfigurationOutcome portConfiguration(const CodeBaseConfiguration& configuration, const ConfigurationLimits& limits = {});

struct CodeBaseResults {
    CodeBase codeBase;
    std::vector<ConfigurationOutcome> outcomes; // in the manifest's order
};

CodeBaseResults portCodeBase(const CodeBase& codeBase, const ConfigurationLimits& limits,
                             const std::function<void(const ConfigurationOutcome&, size_t done, size_t total)>& progress = {});

} // namespace iblkit::porting
