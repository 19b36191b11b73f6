#include "codebase_report.hpp"

#include "kit_edits.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

namespace iblkit::porting {
namespace {

using compiler::CrossTarget;

std::string percent(size_t part, size_t whole) {
    return whole == 0 ? "—" : fmt::format("{:.0f} %", 100.0 * double(part) / double(whole));
}

std::string escapeCell(std::string text) {
    std::string escaped;
    for (const char c : text) {
        if (c == '|') escaped += "\\|";
        else if (c == '\n') escaped += "<br>";
        else escaped += c;
    }
    return escaped;
}

std::string shortCommit(const std::string& commit) { return commit.substr(0, 12); }

// ✓ produced and read back, ◐ produced and not read back, ✗ refused by name, · not made.
// ✓ run on all three paths, the same numbers; ◐ the same where run; ✗ they differ (or the run
// crashed); · not run.
const char* pathsMark(const ConfigurationOutcome& outcome) {
    if (outcome.paths.empty()) return "·";
    if (!outcome.pathsAgree) return "✗";
    return outcome.sameNumbersOnEveryPath() ? "✓" : "◐";
}

// The line of a message that says what went wrong: the first naming an error, not the "In file
// included from" before it.
std::string firstLineOf(const std::string& text) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        if (line.find("error") != std::string::npos) return line;
    return text.substr(0, text.find('\n'));
}

// Why the seeded run shows less than ✓: the first difference, or why it or a path did not run.
std::string runNote(const ConfigurationOutcome& outcome) {
    if (!outcome.disagreement.empty()) return "differs: " + firstLineOf(outcome.disagreement);
    if (!outcome.notRun.empty()) return "not run: " + firstLineOf(outcome.notRun);
    std::string note;
    for (const auto& path : outcome.paths)
        if (!path.ran) note += (note.empty() ? "" : "; ") + path.path + " not run: " + firstLineOf(path.notRun);
    return note.size() > 300 ? note.substr(0, 297) + "..." : note;
}

const char* formMark(const ConfigurationOutcome& outcome, CrossTarget target) {
    const auto found = outcome.forms.find(target);
    if (found == outcome.forms.end()) return "·";
    if (!found->second.produced) return "✗";
    return found->second.message.empty() ? "✓" : "◐";
}

void appendTotals(std::string& out, const std::vector<CodeBaseResults>& results) {
    out += "| code base | commit | configurations | stages | reach SPIR-V | every form | all six forms read back | "
           "same numbers where run | on all three paths | ray tracing, mesh |\n|---|---|--:|---|--:|--:|--:|--:|--:|--:|\n";
    for (const auto& result : results) {
        const auto totals = portingTotals({result});
        std::map<std::string, size_t> stages;
        for (const auto& outcome : result.outcomes) ++stages[outcome.stage];
        std::string stageList;
        for (const auto& [stage, count] : stages) stageList += (stageList.empty() ? "" : ", ") + fmt::format("{} {}", count, stage);
        out += fmt::format("| [{}]({}) | `{}` | {} | {} | {} ({}) | {} ({}) | {} ({}) | {} of {} | {} | {} |\n", result.codeBase.name,
                           result.codeBase.repository, shortCommit(result.codeBase.commit), totals.configurations, stageList,
                           totals.reachedSpirv, percent(totals.reachedSpirv, totals.counted()), totals.everyForm,
                           percent(totals.everyForm, totals.counted()), totals.allSixForms,
                           percent(totals.allSixForms, totals.counted()), totals.sameWhereRun, totals.ran, totals.sameEveryPath,
                           totals.refusedStages);
    }
    const auto all = portingTotals(results);
    out += fmt::format("| **all** | | **{}** | | **{} ({})** | **{} ({})** | **{} ({})** | **{} of {}** | **{}** | **{}** |\n\n",
                       all.configurations, all.reachedSpirv, percent(all.reachedSpirv, all.counted()), all.everyForm,
                       percent(all.everyForm, all.counted()), all.allSixForms, percent(all.allSixForms, all.counted()),
                       all.sameWhereRun, all.ran, all.sameEveryPath, all.refusedStages);
}

void appendCauses(std::string& out, const std::vector<CodeBaseResults>& results) {
    const auto causes = causesOf(results);
    if (causes.empty()) {
        out += "Every configuration that is not ray tracing or mesh has every form.\n\n";
        return;
    }
    out += "| cause | configurations | code bases |\n|---|--:|---|\n";
    for (const auto& cause : causes) {
        std::string bases;
        for (const auto& base : cause.codeBases) bases += (bases.empty() ? "" : ", ") + base;
        out += fmt::format("| {} | {} | {} |\n", escapeCell(cause.cause), cause.count, bases);
    }
    out += "\n";
}

void appendEdits(std::string& out, const std::vector<CodeBaseResults>& results) {
    std::map<std::string, std::map<std::string, size_t>> uses; // edit -> code base -> configurations
    for (const auto& result : results)
        for (const auto& outcome : result.outcomes)
            for (const auto& edit : outcome.kitEdits) ++uses[edit][result.codeBase.name];
    if (uses.empty()) return;
    out += "## What the kit rewrote\n\nThe kit's edits (docs/compiler.md) that the configurations needed, with how many "
           "used each.\n\n| edit | what it does | configurations |\n|---|---|---|\n";
    for (const auto& [edit, bases] : uses) {
        std::string where;
        for (const auto& [base, count] : bases) where += (where.empty() ? "" : ", ") + fmt::format("{} {}", base, count);
        out += fmt::format("| `{}` | {} | {} |\n", edit, escapeCell(std::string(compiler::describeKitEdit(edit))), where);
    }
    out += "\n";
}

void appendConfigurations(std::string& out, const CodeBaseResults& result) {
    const auto& base = result.codeBase;
    out += fmt::format("### {}\n\n[{}]({}) at `{}`", base.name, base.repository, base.repository, base.commit);
    for (const auto& requirement : base.requirements)
        out += fmt::format(", with [{}]({}) at `{}`", requirement.name, requirement.repository, requirement.commit);
    out += ".";
    if (!base.description.empty()) out += " " + base.description;
    out += "\n\n| configuration | stage | build | glsl | essl | msl | hlsl | vulkan-glsl | vulkan-essl | why not | same numbers | run |\n"
           "|---|---|---|:-:|:-:|:-:|:-:|:-:|:-:|---|:-:|---|\n";
    for (const auto& outcome : result.outcomes) {
        out += fmt::format("| `{}` | {} | {} {} |", escapeCell(outcome.label), outcome.stage, outcome.target, outcome.profile);
        for (const auto target : compiler::kCrossTargets) out += fmt::format(" {} |", formMark(outcome, target));
        out += " " + escapeCell(failureCause(outcome)) + " | " + pathsMark(outcome) + " | " + escapeCell(runNote(outcome)) + " |\n";
    }
    out += "\n";
}

nlohmann::json outcomeJson(const ConfigurationOutcome& outcome) {
    nlohmann::json forms = nlohmann::json::object();
    for (const auto& [target, form] : outcome.forms)
        forms[std::string(compiler::crossTargetName(target))] = {{"produced", form.produced}, {"read_back", form.produced && form.message.empty()},
                                                                 {"message", form.message}};
    return {{"configuration", outcome.label}, {"stage", outcome.stage},        {"target", outcome.target},
            {"profile", outcome.profile},     {"refused_stage", outcome.refusedStage}, {"spirv", outcome.reachedSpirv()},
            {"every_form", outcome.everyForm()}, {"error", outcome.error},      {"cause", failureCause(outcome)},
            {"kit_edits", outcome.kitEdits},  {"warnings", outcome.warnings},  {"forms", forms},
            {"same_numbers", pathsMark(outcome)}, {"run", runNote(outcome)}, {"seconds", outcome.seconds}};
}

nlohmann::json totalsJson(const PortingTotals& totals) {
    return {{"configurations", totals.configurations}, {"ray_tracing_or_mesh", totals.refusedStages},
            {"counted", totals.counted()},             {"spirv", totals.reachedSpirv},
            {"every_form", totals.everyForm},          {"all_six_forms", totals.allSixForms},
            {"ran", totals.ran},                       {"same_numbers_where_run", totals.sameWhereRun},
            {"same_numbers_on_every_path", totals.sameEveryPath}, {"differ", totals.differ}};
}

} // namespace

PortingTotals portingTotals(const std::vector<CodeBaseResults>& results) {
    PortingTotals totals;
    for (const auto& result : results)
        for (const auto& outcome : result.outcomes) {
            ++totals.configurations;
            if (outcome.refusedStage) {
                ++totals.refusedStages;
                continue;
            }
            totals.reachedSpirv += outcome.reachedSpirv();
            totals.everyForm += outcome.everyForm();
            totals.allSixForms += outcome.allSixForms();
            totals.ran += !outcome.paths.empty();
            totals.sameWhereRun += outcome.sameNumbersWhereRun();
            totals.sameEveryPath += outcome.sameNumbersOnEveryPath();
            totals.differ += !outcome.paths.empty() && !outcome.pathsAgree;
        }
    return totals;
}

std::vector<CauseCount> causesOf(const std::vector<CodeBaseResults>& results) {
    std::map<std::string, CauseCount> byCause;
    for (const auto& result : results)
        for (const auto& outcome : result.outcomes) {
            if (outcome.refusedStage) continue;
            const auto cause = failureCause(outcome);
            if (cause.empty()) continue;
            auto& entry = byCause[cause];
            entry.cause = cause;
            ++entry.count;
            if (std::find(entry.codeBases.begin(), entry.codeBases.end(), result.codeBase.name) == entry.codeBases.end())
                entry.codeBases.push_back(result.codeBase.name);
        }
    std::vector<CauseCount> causes;
    for (auto& [cause, entry] : byCause) causes.push_back(std::move(entry));
    std::stable_sort(causes.begin(), causes.end(), [](const auto& a, const auto& b) { return a.count > b.count; });
    return causes;
}

std::string codeBaseMarkdown(const std::vector<CodeBaseResults>& results, const std::string& command) {
    const auto totals = portingTotals(results);
    std::string out = "# Porting real code\n\nGenerated by `" + command + "`; do not edit it by hand.\n\n";
    out += fmt::format("{} configurations from {} code bases, each compiled as its own build compiles it (file, entry, "
                       "profile, defines, include folders, flags; the manifests are in "
                       "[`docs/porting-real-code/`](porting-real-code/)). Of the {} that are not ray tracing or mesh "
                       "shaders (the whole stages the kit refuses), **{} ({}) reach valid SPIR-V** (spirv-val, Vulkan 1.1) "
                       "and **{} ({}) have every form**: each of the six produced and read back by the compiler that "
                       "reads it, or refused by name because its language cannot express the shader (wave operations "
                       "in OpenGL GLSL, doubles in ESSL); {} ({}) have all six read back.\n\n",
                       totals.configurations, results.size(), totals.counted(), totals.reachedSpirv,
                       percent(totals.reachedSpirv, totals.counted()), totals.everyForm,
                       percent(totals.everyForm, totals.counted()), totals.allSixForms,
                       percent(totals.allSixForms, totals.counted()));
    out += fmt::format("Each that reaches SPIR-V is then run with seeded resources (every resource filled with seeded "
                       "values in its valid range; a vertex or pixel shader alone drawn with a stage the kit writes; "
                       "`iblkit run --api all`'s three paths: Vulkan from the SPIR-V, Vulkan from the HLSL form compiled "
                       "anew, OpenGL from the GLSL form, each within 4 ULP or 1e-6 of Vulkan's values). "
                       "**{} ran; {} wrote the same numbers on every path that could take them**, {} on all three; "
                       "{} differ.\n\n",
                       totals.ran, totals.sameWhereRun, totals.sameEveryPath, totals.differ);
    out += "## Code bases\n\n";
    appendTotals(out, results);
    out += "## Why the rest do not\n\nEach configuration without every form, by the first thing that stopped it: the "
           "kit's refusal with its place, names and numbers taken out, or the first form not read back.\n\n";
    appendCauses(out, results);
    appendEdits(out, results);
    out += "## Every configuration\n\nForms: ✓ produced and read back; ◐ produced, not read back; ✗ refused by name (its "
           "language cannot express the shader); · not made. Same numbers: ✓ run on all three paths, which agree; ◐ they "
           "agree where run (the run column says why a path could not take the shader); ✗ they differ, or the run "
           "crashed; · not run.\n\n";
    for (const auto& result : results) appendConfigurations(out, result);
    return out;
}

std::string codeBaseJson(const std::vector<CodeBaseResults>& results) {
    nlohmann::json bases = nlohmann::json::array();
    for (const auto& result : results) {
        nlohmann::json outcomes = nlohmann::json::array();
        for (const auto& outcome : result.outcomes) outcomes.push_back(outcomeJson(outcome));
        bases.push_back({{"name", result.codeBase.name},
                         {"repository", result.codeBase.repository},
                         {"commit", result.codeBase.commit},
                         {"totals", totalsJson(portingTotals({result}))},
                         {"configurations", outcomes}});
    }
    nlohmann::json causes = nlohmann::json::array();
    for (const auto& cause : causesOf(results))
        causes.push_back({{"cause", cause.cause}, {"count", cause.count}, {"code_bases", cause.codeBases}});
    return nlohmann::json{{"totals", totalsJson(portingTotals(results))}, {"causes", causes}, {"code_bases", bases}}.dump(1) + "\n";
}

} // namespace iblkit::porting
