#include "codebase_run.hpp"

#include "bounded_child.hpp"
#include "compile_error.hpp"
#include "compiler.hpp"
#include "seeded_run.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <regex>
#include <sstream>

namespace iblkit::porting {
namespace {

using compiler::CrossTarget;
using nlohmann::json;

std::string refusedStageError(const CodeBaseConfiguration& configuration) {
    return configuration.options.source.string() + ": error: '" + configuration.profile.text + "' is a profile of " +
           std::string(profileStageName(configuration.profile.stage)) +
           " shaders: glslang's HLSL frontend has no such stage (supported: vertex, hull, domain, geometry, pixel, compute)";
}

json formsJson(const std::map<CrossTarget, FormOutcome>& forms) {
    json result = json::object();
    for (const auto& [target, form] : forms)
        result[std::string(compiler::crossTargetName(target))] = {{"produced", form.produced}, {"message", form.message}};
    return result;
}

std::map<CrossTarget, FormOutcome> formsFrom(const json& value) {
    std::map<CrossTarget, FormOutcome> forms;
    for (const auto target : compiler::kCrossTargets) {
        const std::string name(compiler::crossTargetName(target));
        if (value.contains(name)) forms[target] = {value[name]["produced"].get<bool>(), value[name]["message"].get<std::string>()};
    }
    return forms;
}

// The child's whole work: compile, every form, read each back.
std::string compileInChild(const CodeBaseConfiguration& configuration) {
    const auto shader = compiler::compileShader(configuration.options);
    return json{{"edits", shader.kitEdits}, {"warnings", shader.warnings},
                {"forms", formsJson(formOutcomes(shader, configuration.options))}}
        .dump();
}

// The child's work for the seeded run: compile again (the reflection holds the varyings), run on
// every path, say what each did.
std::string runSeededInChild(const CodeBaseConfiguration& configuration) {
    const auto shader = compiler::compileShader(configuration.options);
    auto seeded = run::seededRun(configuration.options, shader.reflection);
    if (const auto* why = std::get_if<std::string>(&seeded)) return json{{"not_run", *why}}.dump();
    std::ostringstream log;
    run::RunOptions options;
    options.api = run::RunApi::All;
    options.timeout = std::chrono::seconds(30);
    try {
        const auto summary = run::executeRunOnPaths(std::get<run::RunSpec>(seeded), options, log);
        json paths = json::array();
        for (const auto& path : summary.paths) paths.push_back({{"path", path.path}, {"ran", path.ran}, {"not_run", path.notRun}});
        std::string disagreement;
        std::istringstream lines(log.str());
        for (std::string line; disagreement.empty() && std::getline(lines, line);)
            if (line.rfind("FAIL", 0) == 0) disagreement = line;
        return json{{"paths", paths}, {"agree", summary.pathsAgree}, {"disagreement", disagreement}}.dump();
    } catch (const std::exception& error) { // the device lacks what the shader needs, a resource it cannot make
        return json{{"not_run", error.what()}}.dump();
    }
}

void readSeededRun(const json& result, ConfigurationOutcome& outcome) {
    if (result.contains("not_run")) {
        outcome.notRun = result["not_run"].get<std::string>();
        return;
    }
    for (const auto& path : result["paths"])
        outcome.paths.push_back({path["path"].get<std::string>(), path["ran"].get<bool>(), false, path["not_run"].get<std::string>()});
    outcome.pathsAgree = result["agree"].get<bool>();
    outcome.disagreement = result["disagreement"].get<std::string>();
}

// The line that says what went wrong: the first error, not the "In file included from" before it.
std::string errorLine(const std::string& message) {
    size_t start = 0;
    while (start < message.size()) {
        const auto end = message.find('\n', start);
        const auto line = message.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (line.find("error") != std::string::npos || line.find("ERROR") != std::string::npos) return line;
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return message.substr(0, message.find('\n'));
}

// Places, quoted names and numbers out of a message, so that one cause groups its instances.
std::string withoutParticulars(std::string line) {
    static const std::regex kPlace(R"(^.*?:(\d+:)?(\d+:)? ?(error|warning): (ERROR: .*?:\d+: )?)");
    static const std::regex kLineCol(R"(\(\d+:\d+\))");
    static const std::regex kNumber(R"(\b\d+\b)");
    line = std::regex_replace(line, kPlace, "", std::regex_constants::format_first_only);
    line = std::regex_replace(line, kLineCol, "");
    line = std::regex_replace(line, kNumber, "N");
    return line.size() > 160 ? line.substr(0, 157) + "..." : line;
}

} // namespace

bool ConfigurationOutcome::everyForm() const {
    return reachedSpirv() && std::all_of(forms.begin(), forms.end(), [](const auto& entry) {
               return !entry.second.produced || entry.second.message.empty();
           });
}

bool ConfigurationOutcome::sameNumbersWhereRun() const { return !paths.empty() && pathsAgree; }

bool ConfigurationOutcome::sameNumbersOnEveryPath() const {
    return sameNumbersWhereRun() && std::all_of(paths.begin(), paths.end(), [](const auto& path) { return path.ran; });
}

bool ConfigurationOutcome::allSixForms() const {
    return reachedSpirv() && forms.size() == std::size(compiler::kCrossTargets) &&
           std::all_of(forms.begin(), forms.end(),
                       [](const auto& entry) { return entry.second.produced && entry.second.message.empty(); });
}

std::string failureCause(const ConfigurationOutcome& outcome) {
    if (!outcome.reachedSpirv()) return withoutParticulars(errorLine(outcome.error));
    for (const auto& [target, form] : outcome.forms)
        if (form.produced && !form.message.empty())
            return std::string(compiler::crossTargetName(target)) + " form not read back: " +
                   withoutParticulars(errorLine(form.message));
    return "";
}

ConfigurationOutcome portConfiguration(const CodeBaseConfiguration& configuration, const ConfigurationLimits& limits) {
    ConfigurationOutcome outcome;
    outcome.label = configuration.label;
    outcome.stage = profileStageName(configuration.profile.stage);
    outcome.target = buildTargetName(configuration.target);
    outcome.profile = configuration.profile.text;
    outcome.refusedStage = configuration.refusedStage();
    if (outcome.refusedStage) {
        outcome.error = refusedStageError(configuration);
        return outcome;
    }
    const auto start = std::chrono::steady_clock::now();
    try {
        const auto result = json::parse(compiler::runInBoundedChild(
            [&] { return compileInChild(configuration); },
            {limits.cpuSeconds, limits.wallSeconds, limits.extraMegabytes}, configuration.options.source.string(),
            "the kit's compiler", " on this configuration"));
        outcome.kitEdits = result["edits"].get<std::vector<std::string>>();
        outcome.warnings = result["warnings"].get<std::vector<std::string>>();
        outcome.forms = formsFrom(result["forms"]);
    } catch (const compiler::CompileError& error) {
        outcome.error = error.what();
        if (outcome.error.empty()) outcome.error = configuration.options.source.string() + ": error: compilation failed";
    }
    if (outcome.reachedSpirv()) {
        try {
            readSeededRun(json::parse(compiler::runInBoundedChild(
                              [&] { return runSeededInChild(configuration); },
                              {limits.cpuSeconds, limits.wallSeconds, limits.extraMegabytes}, configuration.options.source.string(),
                              "the seeded run", " of this configuration")),
                          outcome);
        } catch (const compiler::CompileError& error) { // a crash or a limit: a finding, named
            outcome.disagreement = error.what();
            outcome.paths.push_back({"vulkan", false, false, error.what()});
        }
    }
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return outcome;
}

CodeBaseResults portCodeBase(const CodeBase& codeBase, const ConfigurationLimits& limits,
                             const std::function<void(const ConfigurationOutcome&, size_t, size_t)>& progress) {
    CodeBaseResults results{codeBase, {}};
    for (const auto& configuration : codeBase.configurations) {
        results.outcomes.push_back(portConfiguration(configuration, limits));
        if (progress) progress(results.outcomes.back(), results.outcomes.size(), codeBase.configurations.size());
    }
    return results;
}

} // namespace iblkit::porting
