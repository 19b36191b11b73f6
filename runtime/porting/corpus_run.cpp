#include "corpus_run.hpp"

#include "compile_error.hpp"
#include "compiler.hpp"
#include "glsl_frontend.hpp"
#include "seeded_run.hpp"

#include <algorithm>
#include <sstream>

namespace iblkit::porting {
namespace {

using compiler::CrossTarget;

// Reads a produced form back; throws CompileError with the reader's message.
void readBack(const compiler::CompiledShader& shader, const compiler::CompileOptions& options, CrossTarget target,
              const std::string& source) {
    const auto stage = shader.reflection.stage;
    const std::string name = shader.sourceName + " (" + std::string(compiler::crossTargetName(target)) + " form)";
    switch (target) {
    case CrossTarget::Glsl:
    case CrossTarget::Essl: compiler::compileOpenGlGlsl(source, stage, name); return;
    case CrossTarget::VulkanGlsl:
    case CrossTarget::VulkanEssl: compiler::compileVulkanGlsl(source, stage, name); return;
    case CrossTarget::Hlsl: {
        auto again = options;
        again.source = name; // its messages name the form, not the corpus shader
        again.sourceText = source;
        again.stage = stage;
        again.entryPoint = shader.reflection.entryPoint;
        compiler::compileShader(again);
        return;
    }
    case CrossTarget::Msl: return;
    }
}

} // namespace

std::map<CrossTarget, FormOutcome> formOutcomes(const compiler::CompiledShader& shader, const compiler::CompileOptions& options) {
    const auto forms = compiler::crossCompileForms(shader, {std::begin(compiler::kCrossTargets), std::end(compiler::kCrossTargets)});
    std::map<CrossTarget, FormOutcome> outcomes;
    for (const auto& [target, reason] : forms.refused) outcomes[target] = {false, reason};
    for (const auto& [target, form] : forms.produced) {
        try {
            readBack(shader, options, target, form.source);
            outcomes[target] = {true, ""};
        } catch (const compiler::CompileError& error) {
            outcomes[target] = {true, error.what()};
        }
    }
    return outcomes;
}

namespace {

// Every path of the run; `seeded` runs have no expectations, so only the paths' agreement counts.
void carryOutRun(const run::RunSpec& spec, bool seeded, run::RunOptions options, ShaderOutcome& outcome) {
    std::ostringstream log;
    options.api = run::RunApi::All;
    outcome.seeded = seeded;
    try {
        const auto summary = run::executeRunOnPaths(spec, options, log);
        outcome.paths = summary.paths;
        outcome.pathsAgree = summary.pathsAgree;
        outcome.run = seeded && summary.passed ? RunOutcome::Seeded : summary.passed ? RunOutcome::Passed : RunOutcome::Failed;
        outcome.runLog = log.str();
    } catch (const std::exception& error) { // RunError, CompileError, VulkanError: the run could not be carried out
        // A seeded run has nothing to meet: the device lacking what the shader needs is a reason not to run it.
        outcome.run = seeded ? RunOutcome::NotRun : RunOutcome::Failed;
        (seeded ? outcome.notRun : outcome.runLog) = seeded ? std::string(error.what()) : log.str() + error.what();
    }
}

bool contains(const std::vector<std::string>& lines, const std::string& words) {
    return std::any_of(lines.begin(), lines.end(), [&](const std::string& line) { return line.find(words) != std::string::npos; });
}

// How a form's outcome differs from what the manifest says of it, or "".
std::string formMismatch(const CorpusFeature& feature, CrossTarget target, const FormOutcome& form) {
    const std::string name(compiler::crossTargetName(target));
    const bool refused = feature.refusedForms.count(target) > 0, unread = feature.unreadForms.count(target) > 0;
    if (!form.produced) return refused ? "" : name + " was refused: " + form.message;
    if (refused) return name + " was produced, but the manifest says it is refused";
    if (unread && form.message.empty()) return name + " reads back, but the manifest says it does not";
    if (!unread && !form.message.empty()) return name + " does not read back: " + form.message;
    return "";
}

void judgeCompiled(const CorpusFeature& feature, const ShaderOutcome& shader, FeatureOutcome& outcome) {
    auto& mismatches = outcome.mismatches;
    for (const auto& edit : feature.kitEdits)
        if (std::find(shader.kitEdits.begin(), shader.kitEdits.end(), edit) == shader.kitEdits.end())
            mismatches.push_back("the kit's edit '" + edit + "' did not happen");
    if (!feature.warning.empty() && !contains(shader.warnings, feature.warning))
        mismatches.push_back("no warning says '" + feature.warning + "'");
    for (const auto& [target, form] : shader.forms)
        if (auto mismatch = formMismatch(feature, target, form); !mismatch.empty()) mismatches.push_back(std::move(mismatch));
    if (shader.run == RunOutcome::Failed)
        mismatches.push_back(std::string(shader.seeded ? "its seeded run failed: " : "its run file failed: ") + shader.runLog);
    outcome.status = !feature.kitEdits.empty() ? FeatureStatus::Lowered
                     : !feature.warning.empty() ? FeatureStatus::Warned
                                                : FeatureStatus::Supported;
}

} // namespace

ShaderOutcome runCorpusShader(const CorpusShader& corpusShader, const run::RunOptions& runOptions) {
    ShaderOutcome outcome;
    outcome.name = corpusShader.name;
    compiler::ShaderReflection reflection;
    try {
        const auto shader = compiler::compileShader(corpusShader.options);
        outcome.warnings = shader.warnings;
        outcome.kitEdits = shader.kitEdits;
        outcome.forms = formOutcomes(shader, corpusShader.options);
        reflection = shader.reflection;
    } catch (const compiler::CompileError& error) {
        outcome.compileError = error.what();
        return outcome;
    }
    if (corpusShader.runFile) {
        try {
            carryOutRun(run::readRunFile(*corpusShader.runFile), false, runOptions, outcome);
        } catch (const std::exception& error) {
            outcome.run = RunOutcome::Failed;
            outcome.runLog = error.what();
        }
        return outcome;
    }
    auto seeded = run::seededRun(corpusShader.options, reflection);
    if (auto* why = std::get_if<std::string>(&seeded)) outcome.notRun = *why;
    else carryOutRun(std::get<run::RunSpec>(seeded), true, runOptions, outcome);
    return outcome;
}

std::string_view statusName(FeatureStatus status) {
    switch (status) {
    case FeatureStatus::Supported: return "supported";
    case FeatureStatus::Lowered: return "lowered by the kit";
    case FeatureStatus::Warned: return "compiled, with a warning";
    case FeatureStatus::Refused: return "refused";
    }
    return "";
}

FeatureOutcome judgeFeature(const CorpusFeature& feature, const ShaderOutcome& shader) {
    FeatureOutcome outcome{feature, FeatureStatus::Refused, {}};
    const bool refused = !shader.compileError.empty();
    if (refused && feature.error.empty()) outcome.mismatches.push_back("it was refused: " + shader.compileError);
    if (!refused && !feature.error.empty()) outcome.mismatches.push_back("it compiled, but the manifest says it is refused");
    if (refused && !feature.error.empty() && shader.compileError.find(feature.error) == std::string::npos)
        outcome.mismatches.push_back("its error does not say '" + feature.error + "': " + shader.compileError);
    if (!refused) judgeCompiled(feature, shader, outcome);
    return outcome;
}

const ShaderOutcome& CorpusResults::shaderNamed(const std::string& name) const {
    return *std::find_if(shaders.begin(), shaders.end(), [&](const ShaderOutcome& outcome) { return outcome.name == name; });
}

bool CorpusResults::agrees() const {
    return std::all_of(features.begin(), features.end(), [](const FeatureOutcome& f) { return f.mismatches.empty(); });
}

CorpusResults runCorpus(const CorpusManifest& manifest, const run::RunOptions& runOptions,
                        const std::function<void(const std::string&)>& progress) {
    CorpusResults results;
    for (const auto& shader : manifest.shaders) {
        results.shaders.push_back(runCorpusShader(shader, runOptions));
        if (progress) progress(shader.name);
    }
    for (const auto& feature : manifest.features) results.features.push_back(judgeFeature(feature, results.shaderNamed(feature.shader)));
    return results;
}

} // namespace iblkit::porting
